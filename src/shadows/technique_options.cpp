#include "shadows/technique_options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra {

std::string OptionSpec::usage() const {
  switch (kind) {
    case OptionKind::Flag: return "--" + name;
    case OptionKind::Integer: return "--" + name + " N";
    case OptionKind::Choice: return fmt::format("--{} {}", name, fmt::join(choices, "|"));
    case OptionKind::Number: return "--" + name + " X";
  }
  return "--" + name;
}

const OptionSpec* TechniqueOptionTable::find(const std::string& name) const {
  for (const OptionSpec& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

void TechniqueOptionTable::validate(const std::any& options) const {
  PENUMBRA_CHECK(options.type() == defaults_.type(), "the options given are not this technique's");
  for (const OptionSpec& s : specs_) {
    const std::string value = s.get(options);
    if (s.kind == OptionKind::Integer) parseInteger(value, s.min, s.max, "--" + s.name);
    if (s.kind == OptionKind::Number)
      parseNumber(value, s.number_min, s.number_max, "--" + s.name);
    PENUMBRA_CHECK(s.kind != OptionKind::Choice || value != "unknown",
                   "--{} holds a value that is none of {}", s.name, fmt::join(s.choices, ", "));
  }
  if (check_) check_(options);
}

int64_t parseInteger(const std::string& text, int64_t min, int64_t max, const std::string& what) {
  // strtoll alone accepts leading spaces, a '+' and trailing junk ("64abc"): only digits with an
  // optional leading '-' are a number here.
  const size_t digits_from = !text.empty() && text[0] == '-' ? 1 : 0;
  bool digits = text.size() > digits_from;
  for (size_t i = digits_from; i < text.size(); ++i)
    digits = digits && text[i] >= '0' && text[i] <= '9';
  PENUMBRA_CHECK(digits, "{} takes a whole number, not '{}'", what, text);
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  PENUMBRA_CHECK(errno != ERANGE && value >= min && value <= max,
                 "{} is {} but must be in {}..{}", what, text, min, max);
  return int64_t(value);
}

double parseNumber(const std::string& text, double min, double max, const std::string& what) {
  // strtod alone accepts leading spaces, '+', "nan", "inf", hex and trailing junk: only digits,
  // one optional leading '-', a '.', and an exponent (e/E, optional sign, digits) are a number.
  bool ok = !text.empty();
  size_t i = 0;
  if (ok && text[i] == '-') ++i;
  size_t mantissa_digits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++mantissa_digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++mantissa_digits;
  }
  ok = ok && mantissa_digits > 0;
  if (ok && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    size_t exponent_digits = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++exponent_digits;
    ok = exponent_digits > 0;
  }
  ok = ok && i == text.size();
  PENUMBRA_CHECK(ok, "{} takes a number, not '{}'", what, text);
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  PENUMBRA_CHECK(errno != ERANGE && std::isfinite(value) && value >= min && value <= max,
                 "{} is {} but must be in {}..{}", what, text, formatNumber(min),
                 formatNumber(max));
  return value;
}

std::string formatNumber(double value) { return fmt::format("{}", value); }

bool parseFlag(const std::string& text, const std::string& what) {
  if (text == "true" || text == "on" || text == "1") return true;
  if (text == "false" || text == "off" || text == "0") return false;
  throw Error(fmt::format("{} takes true or false, not '{}'", what, text));
}

void throwUnknownOptionChoice(const std::string& what, const std::string& value,
                              const std::vector<std::string>& choices) {
  throw Error(fmt::format("{} takes {}, not '{}'", what, fmt::join(choices, ", "), value));
}

}  // namespace penumbra
