#include "scene/builtin_scenes.h"

#include <algorithm>
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

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const BuiltinEntry& entry : kBuiltins) names.push_back(entry.name);
  return names;
}

bool isBuiltinScene(const std::string& name) {
  return std::any_of(std::begin(kBuiltins), std::end(kBuiltins),
                     [&](const BuiltinEntry& entry) { return name == entry.name; });
}

Scene builtinScene(const std::string& name) {
  for (const BuiltinEntry& entry : kBuiltins) {
    if (name != entry.name) continue;
    Scene scene = entry.make();
    scene.name = name;
    scene.finalize();
    return scene;
  }
  throw Error(fmt::format("unknown built-in scene '{}' (built-in scenes: {})", name,
                          fmt::join(builtinSceneNames(), ", ")));
}

}  // namespace penumbra
