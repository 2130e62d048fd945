#include "shadows/technique.h"

#include <iterator>

#include <fmt/format.h>

#include "core/error.h"
#include "shadows/technique_table.h"

namespace penumbra {
namespace {

// The table's techniques, then the registered ones. Built on first use, so a registration
// during static initialisation (a test's own technique) finds the table already there. A deque:
// configurations point at their TechniqueInfo, which a later registration must not move.
std::deque<TechniqueInfo>& registry() {
  static std::deque<TechniqueInfo> all = [] {
    std::vector<TechniqueInfo> table = builtinTechniques();
    return std::deque<TechniqueInfo>(std::make_move_iterator(table.begin()),
                                     std::make_move_iterator(table.end()));
  }();
  return all;
}

bool answersTo(const TechniqueInfo& info, const std::string& name) {
  if (info.name == name) return true;
  for (const std::string& alias : info.aliases)
    if (alias == name) return true;
  return false;
}

}  // namespace

const std::deque<TechniqueInfo>& techniques() { return registry(); }

std::vector<std::string> techniqueNames() {
  std::vector<std::string> names;
  for (const TechniqueInfo& info : registry()) names.push_back(info.name);
  return names;
}

const TechniqueInfo& findTechnique(const std::string& name) {
  for (const TechniqueInfo& info : registry())
    if (answersTo(info, name)) return info;
  throw Error(fmt::format("unknown technique '{}' (known: {})", name,
                          fmt::join(techniqueNames(), ", ")));
}

void registerTechnique(TechniqueInfo info) {
  PENUMBRA_CHECK(!info.name.empty() && info.prepare, "a technique needs a name and a factory");
  for (const TechniqueInfo& known : registry()) {
    PENUMBRA_CHECK(!answersTo(known, info.name), "technique name '{}' is taken", info.name);
    for (const std::string& alias : info.aliases)
      PENUMBRA_CHECK(!answersTo(known, alias), "technique name '{}' is taken", alias);
  }
  registry().push_back(std::move(info));
}

TechniqueConfig::TechniqueConfig(const std::string& name)
    : info_(&findTechnique(name)), options_(info_->options.defaults()) {}

void TechniqueConfig::set(const std::string& option, const std::string& value) {
  const OptionSpec* spec = info_->options.find(option);
  if (spec == nullptr) {
    std::vector<std::string> known;
    for (const OptionSpec& s : info_->options.specs()) known.push_back("--" + s.name);
    throw Error(fmt::format("--{} is not an option of technique '{}' ({})", option, info_->name,
                            known.empty()
                                ? std::string("it has none")
                                : fmt::format("its options: {}", fmt::join(known, ", "))));
  }
  try {
    spec->set(options_, value);
  } catch (const Error& e) {
    throw Error(fmt::format("technique '{}': {}", info_->name, e.what()));
  }
}

std::string TechniqueConfig::get(const std::string& option) const {
  const OptionSpec* spec = info_->options.find(option);
  PENUMBRA_CHECK(spec != nullptr, "--{} is not an option of technique '{}'", option, info_->name);
  return spec->get(options_);
}

std::string TechniqueConfig::describe() const {
  const std::string details = info_->options.describe(options_);
  return details.empty() ? info_->name : fmt::format("{} ({})", info_->name, details);
}

std::unique_ptr<PreparedTechnique> prepareTechnique(const TechniqueConfig& config,
                                                    const Scene& scene) {
  try {
    config.validate();
  } catch (const Error& e) {
    throw Error(fmt::format("technique '{}': {}", config.name(), e.what()));
  }
  return config.info().prepare(config.rawOptions(), scene);
}

TechniqueResult renderShadows(const TechniqueConfig& config, const Scene& scene,
                              const Light& light, const View& view, const EyeBuffers& eye,
                              const RenderContext& context) {
  PENUMBRA_CHECK(eye.depth.width() == view.width && eye.depth.height() == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", eye.depth.width(),
                 eye.depth.height(), view.width, view.height);
  return prepareTechnique(config, scene)->render(light, view, eye, context);
}

Image<float>& debugLayer(std::vector<DebugLayer>& layers, const std::string& name,
                         const std::string& description, int width, int height) {
  for (DebugLayer& layer : layers) {
    if (layer.name != name) continue;
    PENUMBRA_CHECK(layer.values.width() == width && layer.values.height() == height,
                   "debug layer '{}' is {}x{}, asked for at {}x{}", name, layer.values.width(),
                   layer.values.height(), width, height);
    return layer.values;
  }
  layers.push_back({name, description, Image<float>(width, height, 0.0f)});
  return layers.back().values;
}

const char* casterCullingName(CasterCullingMode mode) {
  switch (mode) {
    case CasterCullingMode::Off: return "off";
    case CasterCullingMode::On: return "on";
    case CasterCullingMode::Auto: return "auto";
  }
  return "auto";
}

CasterCullingMode parseCasterCulling(const std::string& name) {
  for (const CasterCullingMode mode :
       {CasterCullingMode::Off, CasterCullingMode::On, CasterCullingMode::Auto})
    if (name == casterCullingName(mode)) return mode;
  throw Error(fmt::format("caster culling '{}' is not one of off, on, auto", name));
}

const DebugLayer* findDebugLayer(const std::vector<DebugLayer>& layers, const std::string& name) {
  for (const DebugLayer& layer : layers)
    if (layer.name == name) return &layer;
  return nullptr;
}

}  // namespace penumbra
