#include "viewer_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra::viewer {

namespace {

const std::vector<std::pair<Overlay, const char*>> kOverlayNames = {
    {Overlay::Shaded, "shaded"},   {Overlay::Visibility, "visibility"},
    {Overlay::Penumbra, "penumbra"}, {Overlay::Depth, "depth"},
    {Overlay::TileDepthRange, "tiles"}, {Overlay::SilhouetteEdges, "silhouette-edges"},
    {Overlay::WedgeFootprints, "wedge-footprints"}, {Overlay::CulledTiles, "culled-tiles"}};
const std::vector<std::pair<CompareMode, const char*>> kCompareNames = {
    {CompareMode::Off, "off"}, {CompareMode::Split, "split"}, {CompareMode::Heatmap, "heatmap"}};

template <class Enum>
Enum parseName(const std::vector<std::pair<Enum, const char*>>& names, const std::string& name,
               const char* what) {
  std::vector<std::string> known;
  for (const auto& [value, text] : names) {
    if (name == text) return value;
    known.push_back(text);
  }
  throw Error(fmt::format("unknown {} '{}' (known: {})", what, name, fmt::join(known, ", ")));
}

template <class Enum>
std::string nameOf(const std::vector<std::pair<Enum, const char*>>& names, Enum value) {
  for (const auto& [v, text] : names)
    if (v == value) return text;
  return "?";
}

TechniqueEntry entryFor(const TechniqueInfo& info) {
  TechniqueEntry entry;
  entry.info = &info;
  const std::any defaults = info.options.defaults();
  for (const OptionSpec& spec : info.options.specs()) {
    entry.options.push_back({&spec, spec.get(defaults)});
  }
  return entry;
}

TechniqueConfig configOf(const TechniqueEntry& entry) {
  TechniqueConfig config(entry.info->name);
  for (const OptionControl& option : entry.options) config.set(option.spec->name, option.value);
  return config;
}

Light& selected(ViewerModel& model) {
  PENUMBRA_CHECK(model.selected_light < model.lights.size(), "no light is selected");
  return model.lights[model.selected_light];
}

}  // namespace

std::string overlayName(Overlay overlay) { return nameOf(kOverlayNames, overlay); }
std::string compareModeName(CompareMode mode) { return nameOf(kCompareNames, mode); }
const std::vector<Overlay>& allOverlays() {
  static const std::vector<Overlay> all = {
      Overlay::Shaded,         Overlay::Visibility,      Overlay::Penumbra,
      Overlay::Depth,          Overlay::TileDepthRange,  Overlay::SilhouetteEdges,
      Overlay::WedgeFootprints, Overlay::CulledTiles};
  return all;
}

std::string overlayLayer(Overlay overlay) {
  switch (overlay) {
    case Overlay::SilhouetteEdges: return kSilhouetteEdgesLayer;
    case Overlay::WedgeFootprints: return kWedgeFootprintsLayer;
    case Overlay::CulledTiles: return kCulledTilesLayer;
    default: return "";
  }
}

void setOverlay(ViewerModel& model, Overlay overlay) {
  if (overlayLayer(overlay).empty() != overlayLayer(model.overlay).empty()) ++model.generation;
  model.overlay = overlay;
}
const std::vector<CompareMode>& allCompareModes() {
  static const std::vector<CompareMode> all = {CompareMode::Off, CompareMode::Split,
                                               CompareMode::Heatmap};
  return all;
}
Overlay parseOverlay(const std::string& name) { return parseName(kOverlayNames, name, "overlay"); }
CompareMode parseCompareMode(const std::string& name) {
  return parseName(kCompareNames, name, "compare mode");
}

ViewerModel makeViewerModel(const Scene& scene, const std::string& technique, int width,
                            int height) {
  ViewerModel model;
  for (const TechniqueInfo& info : techniques()) model.techniques.push_back(entryFor(info));
  model.camera = scene.camera;
  model.lights = scene.lights;
  model.width = width > 0 ? width : scene.settings.width;
  model.height = height > 0 ? height : scene.settings.height;
  selectTechnique(model, technique);
  return model;
}

const TechniqueEntry& currentTechnique(const ViewerModel& model) {
  return model.techniques.at(model.technique);
}

void selectTechnique(ViewerModel& model, const std::string& name) {
  const TechniqueInfo& info = findTechnique(name);  // resolves aliases, names the known
  for (size_t i = 0; i < model.techniques.size(); ++i) {
    if (model.techniques[i].info == &info) {
      if (model.technique != i) ++model.generation;
      model.technique = i;
      return;
    }
  }
  // Registered after the model was made: it joins the list.
  model.techniques.push_back(entryFor(info));
  model.technique = model.techniques.size() - 1;
  ++model.generation;
}

void setOption(ViewerModel& model, const std::string& name, const std::string& value) {
  TechniqueEntry& entry = model.techniques.at(model.technique);
  TechniqueConfig config = configOf(entry);
  config.set(name, value);
  config.validate();
  for (OptionControl& option : entry.options) {
    // The option's own text of the value ("1" for a flag reads back as "true").
    if (option.spec->name == name) option.value = config.get(name);
  }
  ++model.generation;
}

TechniqueConfig techniqueConfig(const ViewerModel& model) {
  return configOf(currentTechnique(model));
}

TechniqueConfig previewConfig(const ViewerModel& model, std::vector<std::string>& changed) {
  changed.clear();
  TechniqueConfig config = techniqueConfig(model);
  for (const OptionControl& option : currentTechnique(model).options) {
    const OptionSpec& spec = *option.spec;
    if (spec.preview.empty() || spec.preview == option.value) continue;
    // Only where it is cheaper: fewer samples than set, never more.
    if (spec.kind == OptionKind::Integer && std::stoll(spec.preview) >= std::stoll(option.value))
      continue;
    try {
      config.set(spec.name, spec.preview);
      config.validate();
    } catch (const Error&) {
      config.set(spec.name, option.value);  // refused with the other options: keep the value
      continue;
    }
    changed.push_back(spec.name + " " + spec.preview);
  }
  return config;
}

std::vector<std::string> renderFlags(const ViewerModel& model) {
  const TechniqueEntry& entry = currentTechnique(model);
  std::vector<std::string> flags = {"--technique", entry.info->name};
  const std::any defaults = entry.info->options.defaults();
  for (const OptionControl& option : entry.options) {
    const OptionSpec& spec = *option.spec;
    if (option.value == spec.get(defaults)) continue;
    if (spec.kind == OptionKind::Flag) {
      // A command-line flag can only set the value it stands for; the other one is the default.
      flags.push_back("--" + spec.name);
    } else {
      flags.push_back("--" + spec.name);
      flags.push_back(option.value);
    }
  }
  return flags;
}

void selectLight(ViewerModel& model, size_t index) {
  PENUMBRA_CHECK(index < model.lights.size(), "light {} does not exist (the scene has {})", index,
                 model.lights.size());
  model.selected_light = index;
}

void setLightRadius(ViewerModel& model, float radius) {
  Light& light = selected(model);
  if (light.shape == LightShape::Rectangle) return;  // its size is its edges
  light.radius = std::max(0.0f, radius);
  ++model.generation;
}

void setLightIntensity(ViewerModel& model, float intensity) {
  selected(model).intensity = std::max(0.0f, intensity);
  ++model.generation;
}

void setRectangleLight(ViewerModel& model, float width, float height, float turn_degrees) {
  Light& light = selected(model);
  if (light.shape != LightShape::Rectangle) return;
  // The rectangle keeps its plane: u and v turn about their common normal.
  const vec3 u = glm::normalize(light.edge_u), v = glm::normalize(light.edge_v);
  const float a = glm::radians(turn_degrees);
  const vec3 turned_u = std::cos(a) * u + std::sin(a) * v;
  const vec3 turned_v = -std::sin(a) * u + std::cos(a) * v;
  Light rebuilt = rectangleLight(light.center, turned_u * std::max(width, 1e-3f),
                                 turned_v * std::max(height, 1e-3f));
  rebuilt.color = light.color;
  rebuilt.intensity = light.intensity;
  rebuilt.texture = light.texture;
  light = rebuilt;
  ++model.generation;
}

void setDiskNormal(ViewerModel& model, float tilt_degrees, float azimuth_degrees) {
  Light& light = selected(model);
  if (light.shape != LightShape::Disk) return;
  const float tilt = glm::radians(tilt_degrees), azimuth = glm::radians(azimuth_degrees);
  light.normal = glm::normalize(vec3(std::sin(tilt) * std::cos(azimuth), -std::cos(tilt),
                                     std::sin(tilt) * std::sin(azimuth)));
  ++model.generation;
}

}  // namespace penumbra::viewer
