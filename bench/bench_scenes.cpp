#include "bench_scenes.h"

#include <map>
#include <mutex>

#include "scene/builtin_scenes.h"

namespace penumbra {

const Scene& benchScene(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, Scene> scenes;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = scenes.find(name);
  // A scene file or mesh file (penumbra_bench --scene) loads as `penumbra render` loads it.
  if (it == scenes.end()) it = scenes.emplace(name, loadScene(name)).first;
  return it->second;
}

}  // namespace penumbra
