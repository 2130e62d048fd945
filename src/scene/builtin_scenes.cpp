#include "scene/builtin_scenes.h"

#include <algorithm>
#include <string_view>
#include <utility>

#include <fmt/ranges.h>

#include "core/error.h"
#include "scene/builtin_scenes_impl.h"

namespace penumbra {

namespace {

struct BuiltinEntry {
  const char* name;
  Scene (*make)();
};

// The papers' test scenes in spirit (README, "What is in it"), in the order `penumbra scenes`
// lists.
constexpr BuiltinEntry kBuiltins[] = {
    {"spheres", makeSpheresScene},  {"columns", makeColumnsScene},
    {"fractal", makeFractalScene},  {"year2002", makeYear2002Scene},
    {"multilight", makeMultilightScene},
};

constexpr std::string_view kCity = "city";

// "city" or "city:N" (builtin_city_scene.cpp): true for every name of that form, valid size or
// not, so that a bad size is reported as one (builtinScene) rather than as an unknown scene.
bool isCityName(const std::string& name) {
  return name == kCity || (name.starts_with(kCity) && name.size() > kCity.size() &&
                           name[kCity.size()] == ':');
}

Scene cityScene(const std::string& name) {
  int blocks = kDefaultCityBlocks;
  if (name != kCity) {
    const std::string size = name.substr(kCity.size() + 1);
    const bool digits = !size.empty() && size.size() <= 3 &&
                        std::all_of(size.begin(), size.end(), [](char c) { return c >= '0' && c <= '9'; });
    PENUMBRA_CHECK(digits && std::stoi(size) >= 1 && std::stoi(size) <= kMaxCityBlocks,
                   "built-in scene '{}': the size after 'city:' must be a whole number of blocks "
                   "per side in 1..{} (default {})",
                   name, kMaxCityBlocks, kDefaultCityBlocks);
    blocks = std::stoi(size);
  }
  return makeCityScene(blocks);
}

}  // namespace

std::vector<std::string> largeBuiltinSceneNames() { return {std::string(kCity)}; }

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const BuiltinEntry& entry : kBuiltins) names.push_back(entry.name);
  return names;
}

bool isBuiltinScene(const std::string& name) {
  if (isCityName(name)) return true;
  return std::any_of(std::begin(kBuiltins), std::end(kBuiltins),
                     [&](const BuiltinEntry& entry) { return name == entry.name; });
}

Scene builtinScene(const std::string& name) {
  if (isCityName(name)) {
    Scene scene = cityScene(name);
    scene.name = name;
    scene.finalize();
    return scene;
  }
  for (const BuiltinEntry& entry : kBuiltins) {
    if (name != entry.name) continue;
    Scene scene = entry.make();
    scene.name = name;
    scene.finalize();
    return scene;
  }
  throw Error(fmt::format("unknown built-in scene '{}' (built-in scenes: {}, {}[:SIZE])", name,
                          fmt::join(builtinSceneNames(), ", "),
                          fmt::join(largeBuiltinSceneNames(), ", ")));
}

}  // namespace penumbra
