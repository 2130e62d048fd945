#include "scene_file_bench.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "render/frame.h"
#include "shadows/technique.h"
#include "timed_frames.h"

namespace penumbra {
namespace {

// A FrameRenderer (technique prepared once) rendering into one reused FrameResult, as
// `penumbra render --frames N` does: the warm frame of a viewer.
void sceneFrame(benchmark::State& state, const std::string& scene_name,
                const std::string& technique) {
  const Scene& scene = benchScene(scene_name);
  FrameOptions options;
  options.technique = TechniqueConfig(technique);
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  if (!timeWarmFrames(state, renderer, frame)) return;
  state.counters["scene_triangles"] = double(scene.triangleCount());
  state.SetLabel(fmt::format("{} {}x{} {} tris, {}", scene_name, frame.view.width,
                             frame.view.height, scene.triangleCount(), technique));
}

// The value of "--key=value" or "--key value" at argv[i] (advancing i past it), else nullptr.
const char* takeValue(int& i, int argc, char** argv, const std::string& key) {
  const std::string arg = argv[i];
  if (arg.starts_with(key + "=")) return argv[i] + key.size() + 1;
  if (arg == key && i + 1 < argc) return argv[++i];
  return nullptr;
}

}  // namespace

void registerSceneFileBenchmarks(int& argc, char** argv) {
  std::vector<std::string> scenes, techniques;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (const char* v = takeValue(i, argc, argv, "--scene")) {
      scenes.emplace_back(v);
    } else if (const char* t = takeValue(i, argc, argv, "--technique")) {
      techniques.emplace_back(t);
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  if (techniques.empty()) techniques = {"wedge-3pass", "volume"};
  for (const std::string& scene : scenes) {
    for (const std::string& technique : techniques) {
      const std::string name = fmt::format(
          "SceneFrame/{}/{}", std::filesystem::path(scene).stem().string(), technique);
      benchmark::RegisterBenchmark(name.c_str(),
                                   [scene, technique](benchmark::State& s) {
                                     sceneFrame(s, scene, technique);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->MinWarmUpTime(0.05)
          ->MinTime(0.3);
    }
  }
}

}  // namespace penumbra
