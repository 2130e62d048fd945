#pragma once
// A technique's own options: a plain struct with defaults, and a table of specs that set and
// print its fields by name, so the command line, the stats JSON and the conformance suite
// handle every technique's options without knowing them.
//
//   struct VolumeOptions { VolumeMode mode = VolumeMode::Auto; bool two_level = true; };
//   TechniqueOptionTable table = OptionTableBuilder<VolumeOptions>()
//       .choice("volume-mode", "auto, zpass or zfail", &VolumeOptions::mode, {...})
//       .flag("one-level-stencil", "...", &VolumeOptions::two_level, false)
//       .build();
#include <any>
#include <cstdint>
#include <functional>
#include <string>
#include <typeindex>
#include <utility>
#include <vector>

namespace penumbra {

enum class OptionKind {
  Flag,     // a switch: given alone on the command line; value "true" or "false"
  Integer,  // a whole number in [min, max]
  Choice,   // one of `choices`
  Number,   // a finite real number in [number_min, number_max]
};

struct OptionSpec {
  std::string name;  // the flag without dashes: "tile-size"; the stats JSON key is tile_size
  std::string help;
  OptionKind kind = OptionKind::Integer;
  std::vector<std::string> choices;  // Choice
  int64_t min = 0, max = 0;          // Integer
  double number_min = 0, number_max = 0;  // Number
  // A cheaper value for an interactive preview while the view moves (fewer samples or rays),
  // as set() takes it; empty: the option keeps its value. A preview takes it only where it is
  // cheaper than the value set (for an Integer, smaller).
  std::string preview;
  // Sets the field from a command-line value: throws penumbra::Error saying what is wrong.
  std::function<void(std::any& options, const std::string& value)> set;
  std::function<std::string(const std::any& options)> get;  // the value, as set() takes it
  // "--tile-size N" / "--cull none|zmax|full" / "--smooth"
  std::string usage() const;
};

class TechniqueOptionTable {
 public:
  TechniqueOptionTable() = default;
  std::any defaults() const { return defaults_; }
  std::type_index type() const { return std::type_index(defaults_.type()); }
  const std::vector<OptionSpec>& specs() const { return specs_; }
  const OptionSpec* find(const std::string& name) const;
  // Every option back in its range (options set through the typed struct skip set()), then
  // the technique's own consistency checks; throws penumbra::Error saying what is wrong.
  void validate(const std::any& options) const;
  // What differs from nothing: e.g. "auto, cull full, 16x16 tiles"; empty when none.
  std::string describe(const std::any& options) const {
    return describe_ ? describe_(options) : std::string();
  }

 private:
  template <class Options>
  friend class OptionTableBuilder;
  std::any defaults_;
  std::vector<OptionSpec> specs_;
  std::function<void(const std::any&)> check_;
  std::function<std::string(const std::any&)> describe_;
};

// Parses a whole decimal number, nothing else on the line; throws penumbra::Error naming
// `what` when the text is not one or lies outside [min, max].
int64_t parseInteger(const std::string& text, int64_t min, int64_t max, const std::string& what);
// Parses a whole finite decimal number ("0.5", "-2", "1e-3"; no spaces, no leading '+', no
// nan, inf or hex), nothing else on the line; throws penumbra::Error naming `what` when the
// text is not one or lies outside [min, max].
double parseNumber(const std::string& text, double min, double max, const std::string& what);
// The shortest text parseNumber reads back as exactly `value`.
std::string formatNumber(double value);
bool parseFlag(const std::string& text, const std::string& what);  // true/false, on/off, 1/0
[[noreturn]] void throwUnknownOptionChoice(const std::string& what, const std::string& value,
                                           const std::vector<std::string>& choices);

template <class Options>
class OptionTableBuilder {
 public:
  explicit OptionTableBuilder(Options defaults = Options{}) {
    table_.defaults_ = std::move(defaults);
  }

  // A switch that sets `field` to `when_given` (e.g. --one-level-stencil clears two_level).
  OptionTableBuilder& flag(std::string name, std::string help, bool Options::*field,
                           bool when_given = true) {
    OptionSpec& s = add(std::move(name), std::move(help), OptionKind::Flag);
    const std::string what = "--" + s.name;
    s.set = [field, when_given, what](std::any& a, const std::string& v) {
      std::any_cast<Options&>(a).*field = parseFlag(v, what) ? when_given : !when_given;
    };
    s.get = [field, when_given](const std::any& a) {
      return std::any_cast<const Options&>(a).*field == when_given ? "true" : "false";
    };
    return *this;
  }

  // A whole number stored through set/get (a tile level given as a tile size, say); set may
  // throw penumbra::Error for values the range alone does not rule out.
  OptionTableBuilder& integer(std::string name, std::string help, int64_t min, int64_t max,
                              std::function<void(Options&, int64_t)> set,
                              std::function<int64_t(const Options&)> get) {
    OptionSpec& s = add(std::move(name), std::move(help), OptionKind::Integer);
    s.min = min;
    s.max = max;
    const std::string what = "--" + s.name;
    s.set = [set, min, max, what](std::any& a, const std::string& v) {
      set(std::any_cast<Options&>(a), parseInteger(v, min, max, what));
    };
    s.get = [get](const std::any& a) {
      return std::to_string(get(std::any_cast<const Options&>(a)));
    };
    return *this;
  }

  template <class Int>
  OptionTableBuilder& integer(std::string name, std::string help, Int Options::*field,
                              int64_t min, int64_t max) {
    return integer(
        std::move(name), std::move(help), min, max,
        [field](Options& o, int64_t v) { o.*field = Int(v); },
        [field](const Options& o) { return int64_t(o.*field); });
  }

  // A real number in [min, max] (a bias in texels, say).
  OptionTableBuilder& number(std::string name, std::string help, double Options::*field,
                             double min, double max) {
    OptionSpec& s = add(std::move(name), std::move(help), OptionKind::Number);
    s.number_min = min;
    s.number_max = max;
    const std::string what = "--" + s.name;
    s.set = [field, min, max, what](std::any& a, const std::string& v) {
      std::any_cast<Options&>(a).*field = parseNumber(v, min, max, what);
    };
    s.get = [field](const std::any& a) {
      return formatNumber(std::any_cast<const Options&>(a).*field);
    };
    return *this;
  }

  template <class Enum>
  OptionTableBuilder& choice(std::string name, std::string help, Enum Options::*field,
                             std::vector<std::pair<std::string, Enum>> values) {
    OptionSpec& s = add(std::move(name), std::move(help), OptionKind::Choice);
    for (const auto& [text, value] : values) s.choices.push_back(text);
    const std::string what = "--" + s.name;
    const std::vector<std::string> choices = s.choices;
    s.set = [field, values, what, choices](std::any& a, const std::string& v) {
      for (const auto& [text, value] : values) {
        if (v != text) continue;
        std::any_cast<Options&>(a).*field = value;
        return;
      }
      throwUnknownOptionChoice(what, v, choices);
    };
    s.get = [field, values](const std::any& a) {
      for (const auto& [text, value] : values)
        if (std::any_cast<const Options&>(a).*field == value) return text;
      return std::string("unknown");
    };
    return *this;
  }

  // The last option added takes `value` in interactive previews (OptionSpec::preview).
  OptionTableBuilder& preview(std::string value) {
    table_.specs_.back().preview = std::move(value);
    return *this;
  }

  // Consistency checks beyond each option's own range; throw penumbra::Error.
  OptionTableBuilder& check(std::function<void(const Options&)> fn) {
    table_.check_ = [fn](const std::any& a) { fn(std::any_cast<const Options&>(a)); };
    return *this;
  }
  OptionTableBuilder& describe(std::function<std::string(const Options&)> fn) {
    table_.describe_ = [fn](const std::any& a) { return fn(std::any_cast<const Options&>(a)); };
    return *this;
  }
  TechniqueOptionTable build() { return std::move(table_); }

 private:
  // A new spec with its name, help and kind; the caller fills in the rest.
  OptionSpec& add(std::string name, std::string help, OptionKind kind) {
    OptionSpec& s = table_.specs_.emplace_back();
    s.name = std::move(name);
    s.help = std::move(help);
    s.kind = kind;
    return s;
  }
  TechniqueOptionTable table_;
};

}  // namespace penumbra
