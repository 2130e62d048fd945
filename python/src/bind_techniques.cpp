// The technique table as Python data: names, what each claims, and its options with defaults
// and ranges (what `penumbra techniques NAME` prints).
#include <string>

#include "bindings.h"

namespace penumbra::python {

namespace {

const char* kindName(OptionKind kind) {
  switch (kind) {
    case OptionKind::Flag: return "flag";
    case OptionKind::Integer: return "integer";
    case OptionKind::Choice: return "choice";
    case OptionKind::Number: return "number";
  }
  return "?";
}

// The option's default as the Python value a keyword takes (True, 16, 1.0, "full").
py::object typedValue(const OptionSpec& spec, const std::string& text) {
  switch (spec.kind) {
    case OptionKind::Flag: return py::bool_(text == "true");
    case OptionKind::Integer: return py::int_(std::stoll(text));
    case OptionKind::Number: return py::float_(std::stod(text));
    case OptionKind::Choice: return py::str(text);
  }
  return py::none();
}

py::dict optionEntry(const OptionSpec& spec, const std::any& defaults) {
  py::dict option;
  option["name"] = spec.name;
  option["keyword"] = [&] {
    std::string keyword = spec.name;  // tile-size -> tile_size
    for (char& c : keyword) c = c == '-' ? '_' : c;
    return keyword;
  }();
  option["help"] = spec.help;
  option["kind"] = kindName(spec.kind);
  option["default"] = typedValue(spec, spec.get(defaults));
  if (spec.kind == OptionKind::Integer) option["range"] = py::make_tuple(spec.min, spec.max);
  if (spec.kind == OptionKind::Number) {
    option["range"] = py::make_tuple(spec.number_min, spec.number_max);
  }
  if (spec.kind == OptionKind::Choice) option["choices"] = spec.choices;
  return option;
}

py::dict techniqueEntry(const TechniqueInfo& info) {
  py::dict entry;
  entry["name"] = info.name;
  entry["aliases"] = info.aliases;
  entry["summary"] = info.summary;
  py::dict traits;
  traits["soft"] = info.traits.soft;
  traits["ray_traced"] = info.traits.ray_traced;
  traits["exact"] = info.traits.exact;
  traits["covered_mae_bound"] = info.traits.covered_mae_bound;
  traits["penumbra_mae_bound"] = info.traits.penumbra_mae_bound;
  entry["traits"] = traits;
  py::list options;
  const std::any defaults = info.options.defaults();
  for (const OptionSpec& spec : info.options.specs()) options.append(optionEntry(spec, defaults));
  entry["options"] = options;
  return entry;
}

}  // namespace

void bindTechniques(py::module_& m) {
  m.def(
      "techniques",
      [] {
        py::list list;
        for (const TechniqueInfo& info : techniques()) list.append(techniqueEntry(info));
        return list;
      },
      "Every shadow technique: a list of dicts with name, aliases, summary, traits (soft, "
      "ray_traced, exact, error bounds against the oracle) and options (name, keyword, help, "
      "kind, default, and range or choices).");
}

}  // namespace penumbra::python
