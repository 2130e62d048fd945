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

// Built-in scenes with a size, "NAME:N" (N in 1..max; "NAME" alone is the default size).
struct SizedBuiltinEntry {
  std::string_view name;
  Scene (*make)(int size);
  int default_size;
  int max_size;
  const char* unit;  // what N counts, per side
};

constexpr SizedBuiltinEntry kSizedBuiltins[] = {
    {"city", makeCityScene, kDefaultCityBlocks, kMaxCityBlocks, "blocks"},
    {"interior", makeInteriorScene, kDefaultInteriorBays, kMaxInteriorBays, "bays"},
};

// The entry `name` is a form of ("city" or "city:..."), or null. Every "NAME:..." counts, valid
// size or not, so that a bad size is reported as one (builtinScene) rather than as an unknown
// scene.
const SizedBuiltinEntry* sizedEntry(const std::string& name) {
  for (const SizedBuiltinEntry& entry : kSizedBuiltins) {
    if (name == entry.name || (name.starts_with(entry.name) && name.size() > entry.name.size() &&
                               name[entry.name.size()] == ':')) {
      return &entry;
    }
  }
  return nullptr;
}

Scene sizedScene(const SizedBuiltinEntry& entry, const std::string& name) {
  int size = entry.default_size;
  if (name != entry.name) {
    const std::string text = name.substr(entry.name.size() + 1);
    const bool digits =
        !text.empty() && text.size() <= 3 &&
        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    PENUMBRA_CHECK(digits && std::stoi(text) >= 1 && std::stoi(text) <= entry.max_size,
                   "built-in scene '{}': the size after '{}:' must be a whole number of {} per "
                   "side in 1..{} (default {})",
                   name, entry.name, entry.unit, entry.max_size, entry.default_size);
    size = std::stoi(text);
  }
  return entry.make(size);
}

}  // namespace

std::vector<std::string> largeBuiltinSceneNames() {
  std::vector<std::string> names;
  for (const SizedBuiltinEntry& entry : kSizedBuiltins) names.emplace_back(entry.name);
  return names;
}

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const BuiltinEntry& entry : kBuiltins) names.push_back(entry.name);
  return names;
}

bool isBuiltinScene(const std::string& name) {
  if (sizedEntry(name) != nullptr) return true;
  return std::any_of(std::begin(kBuiltins), std::end(kBuiltins),
                     [&](const BuiltinEntry& entry) { return name == entry.name; });
}

Scene builtinScene(const std::string& name) {
  if (const SizedBuiltinEntry* sized = sizedEntry(name)) {
    Scene scene = sizedScene(*sized, name);
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
  std::vector<std::string> names = builtinSceneNames();
  for (const std::string& sized : largeBuiltinSceneNames()) names.push_back(sized + "[:N]");
  throw Error(fmt::format("unknown built-in scene '{}' (built-in scenes: {})", name,
                          fmt::join(names, ", ")));
}

}  // namespace penumbra
