// Hard shadows without aliasing, timed beside the techniques users would compare them with.
//
// HardTechnique/<scene>/<size>/<technique>: the technique alone (prepared once for the scene),
// rendering every light on an eye pass rendered once outside the loop, as
// Technique/columns/640x427/* in frame_bench.cpp does. Techniques: `volume` (auto z-pass /
// z-fail, exact up to ties), `alias-free` (the irregular z-buffer, exact up to ties), the
// oracle's one ray per pixel (`reference --hard`: the answer both must give, from the same
// shaded points) and `shadow-map-1024`, 1024 texels per cube face with PCF 1 x 1 (the plain
// map: approximate; bench/hard_shadow_error.sh times and measures it at other resolutions).
//
// Counters: technique_ms (wall clock per run), <pass>_ms (Stats::time_ms per pass, mean), and
// the alias-free work counters light_samples, tiles_tested, tiles_culled, sample_tests.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "raster/eye_pass.h"
#include "shadows/reference_options.h"
#include "shadows/shadow_map_options.h"
#include "shadows/technique.h"
#include "timed_frames.h"

namespace penumbra {
namespace {

void hardTechnique(benchmark::State& state, const std::string& scene_name, int width, int height,
                   const TechniqueConfig& config) {
  const Scene& scene = benchScene(scene_name);
  const View view = scene.camera.makeView(width, height);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  const std::unique_ptr<PreparedTechnique> prepared = prepareTechnique(config, scene);
  renderUntimed(*prepared, scene, view, eye);
  std::map<std::string, double> pass_ms;
  std::vector<std::string> pass_order;
  Stats last;
  double seconds = 0.0;
  for (auto _ : state) {
    Stats frame;
    const auto start = std::chrono::steady_clock::now();
    for (const Light& light : scene.lights) {
      TechniqueResult result = prepared->render(light, view, eye, RenderContext{});
      benchmark::DoNotOptimize(result.visibility.data());
      frame.add(result.stats);
    }
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& [name, ms] : frame.time_ms) {
      if (pass_ms.emplace(name, 0.0).second) pass_order.push_back(name);
      pass_ms[name] += ms;
    }
    last = std::move(frame);
  }
  if (seconds <= 0.0) return;
  const double n = double(state.iterations());
  state.counters["technique_ms"] = 1e3 * seconds / n;
  for (const std::string& name : pass_order) state.counters[name + "_ms"] = pass_ms[name] / n;
  state.counters["light_samples"] = double(last.counter("light_samples"));
  state.counters["tiles_tested"] = double(last.tiles_tested);
  state.counters["tiles_culled"] = double(last.tiles_culled);
  state.counters["sample_tests"] = double(last.counter("sample_tests"));
  state.SetLabel(fmt::format("{} {}x{}, {}", scene_name, width, height, config.describe()));
}

bool registerAliasFreeBenchmarks() {
  struct Case {
    std::string id;
    TechniqueConfig config;
  };
  std::vector<Case> cases = {{"volume", TechniqueConfig("volume")},
                             {"alias-free", TechniqueConfig("alias-free")}};
  TechniqueConfig oracle("reference");
  oracle.options<ReferenceOptions>().hard = true;
  cases.push_back({"reference-hard", oracle});
  TechniqueConfig map("shadow-map");
  map.options<ShadowMapOptions>().resolution = 1024;
  map.options<ShadowMapOptions>().pcf_kernel = 1;
  cases.push_back({"shadow-map-1024", map});
  struct Size {
    int width, height;
  };
  for (const char* scene : {"columns", "fractal"}) {
    for (const Size size : {Size{640, 427}, Size{1920, 1080}}) {
      for (const Case& c : cases) {
        const std::string name =
            fmt::format("HardTechnique/{}/{}x{}/{}", scene, size.width, size.height, c.id);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [scene = std::string(scene), size,
                                      config = c.config](benchmark::State& s) {
                                       hardTechnique(s, scene, size.width, size.height, config);
                                     })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->MinWarmUpTime(0.05)
            ->MinTime(0.3);
      }
    }
  }
  return true;
}

const bool alias_free_registered = registerAliasFreeBenchmarks();

}  // namespace
}  // namespace penumbra
