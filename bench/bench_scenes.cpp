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
  if (it == scenes.end()) it = scenes.emplace(name, builtinScene(name)).first;
  return it->second;
}

}  // namespace penumbra
