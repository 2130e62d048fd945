#include "scene_file_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "core/parallel.h"
#include "render/frame.h"
#include "shadows/technique.h"

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
  double seconds = 0.0;
  std::vector<std::pair<std::string, double>> passes;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(frame);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(frame.color.data());
    for (const auto& [name, ms] : frame.total.time_ms) {
      auto it = std::find_if(passes.begin(), passes.end(), [&](const auto& p) { return p.first == name; });
      if (it == passes.end()) passes.emplace_back(name, ms);
      else it->second += ms;
    }
  }
  if (seconds <= 0.0) return;
  const double n = double(state.iterations());
  state.counters["fps"] = n / seconds;
  state.counters["frame_ms"] = 1e3 * seconds / n;
  for (const auto& [name, ms] : passes) state.counters[name + "_ms"] = ms / n;
  state.counters["scene_triangles"] = double(scene.triangleCount());
  state.counters["threads"] = double(workerCount());
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
