// Delayed occlusion culling in the eye pass (raster/delay_stream.h; Aila's 2005 thesis, section
// 5.1): `renderEyePass` at 1920x1080 with no stream (`plain`: every triangle rasterized in
// submission order, each pixel depth-tested), a ring of one triangle (`early-z`: the z-max test
// of the cells drawn so far, in submission order) and rings of 64 KB to 8 MB. The buffers are
// the same in every run (tests/test_raster_delay_stream.cpp); the work is what differs.
//
// Scenes: PENUMBRA_DELAY_SCENES, a comma-separated list of scene names or files, each with an
// optional @K for frame K of its camera path (default "city@0,interior@0").
// bench/delay_stream_table.py prints the thesis-style table from the JSON output.
//
// Counters (all from one eye pass; the pixel counters are exact, the time a median of runs):
//   covered          pixels a triangle covers (the optimum: one depth pass each)
//   tested           pixels rasterized: depth tests (Stats::pixels_rasterized)
//   passes           pixels whose depth test passed (depth writes)
//   tested_per_covered, passes_per_covered   the two depth complexities
//   culled_pairs     (triangle, bin tile) pairs the stream culled
//   ring_triangles   triangles the ring holds
//   eye_ms           wall-clock milliseconds per eye pass
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "raster/delay_stream.h"
#include "raster/eye_pass.h"
#include "scene/path.h"

namespace penumbra {
namespace {

struct DelayCase {
  std::string scene;  // as benchScene takes it
  int frame = -1;     // path frame, -1: the scene's own camera
  std::string label;
};

std::vector<DelayCase> delayCases() {
  const char* env = std::getenv("PENUMBRA_DELAY_SCENES");
  std::stringstream list(env != nullptr ? env : "city@0,interior@0");
  std::vector<DelayCase> cases;
  for (std::string item; std::getline(list, item, ',');) {
    if (item.empty()) continue;
    DelayCase c;
    const size_t at = item.rfind('@');
    c.scene = at == std::string::npos ? item : item.substr(0, at);
    if (at != std::string::npos) c.frame = std::atoi(item.c_str() + at + 1);
    c.label = item;
    cases.push_back(c);
  }
  return cases;
}

void delayStream(benchmark::State& state, const DelayCase& c, size_t ring_bytes) {
  Scene scene = benchScene(c.scene);
  if (c.frame >= 0) applyPathFrame(scene, c.frame);
  const View view = scene.camera.makeView(1920, 1080);
  const DepthPassOptions options{.delay_stream_bytes = ring_bytes, .depth_complexity = true};
  Stats last;
  std::vector<double> ms;
  for (auto _ : state) {
    Stats stats;
    const auto start = std::chrono::steady_clock::now();
    EyeBuffers eye = renderEyePass(scene, view, stats, options);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    benchmark::DoNotOptimize(eye.depth.depth.data());
    last = std::move(stats);
  }
  std::sort(ms.begin(), ms.end());
  const double covered = double(last.counter(kEyeCoveredPixels.name));
  state.counters["covered"] = covered;
  state.counters["tested"] = double(last.pixels_rasterized);
  state.counters["passes"] = double(last.counter(kEyeDepthPasses.name));
  state.counters["tested_per_covered"] = double(last.pixels_rasterized) / covered;
  state.counters["passes_per_covered"] = double(last.counter(kEyeDepthPasses.name)) / covered;
  state.counters["culled_pairs"] = double(last.counter(kDelayCulledPairs.name));
  state.counters["ring_triangles"] = double(delayStreamTriangles(ring_bytes));
  state.counters["triangles"] = double(last.triangles);
  state.counters["eye_ms"] = ms.empty() ? 0.0 : ms[ms.size() / 2];
}

bool registerDelayStreamBenchmarks() {
  struct Ring {
    const char* name;
    size_t bytes;
  };
  const Ring rings[] = {{"plain", 0},           {"early-z", 1},         {"64KB", 64 << 10},
                        {"128KB", 128 << 10},   {"256KB", 256 << 10},   {"512KB", 512 << 10},
                        {"1MB", 1 << 20},       {"2MB", 2 << 20},       {"4MB", 4 << 20},
                        {"8MB", 8 << 20}};
  for (const DelayCase& c : delayCases()) {
    for (const Ring& r : rings) {
      const std::string name = fmt::format("DelayStream/{}/1920x1080/{}", c.label, r.name);
      benchmark::RegisterBenchmark(name.c_str(), [c, r](benchmark::State& state) {
        delayStream(state, c, r.bytes);
      })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->MinWarmUpTime(0.05)
          ->MinTime(0.3);
    }
  }
  return true;
}

const bool delay_stream_registered = registerDelayStreamBenchmarks();

}  // namespace
}  // namespace penumbra
