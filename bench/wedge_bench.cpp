// Soft-shadow frames: penumbra wedges against the ray-traced oracle, in one binary and one run.
//
// SoftShadowFrame/columns/<size>/<technique>: FrameRenderer (eye pass, the technique for every
// light, shading) into a reused FrameResult, as a viewer renders frame after frame.
//   wedge-3pass, wedge-1pass: the 2004 restructured algorithm, full z-min/z-max culling, the
//     default 16x16 culling tiles, at 640x427 (the papers' size) and 1920x1080; -tile8: 8x8;
//     -one-level: 16x16 without the two-level stencil (the papers' umbra pass).
//   coverage, heckbert-herf: the 2003 coverage soft shadow volumes and the average of 16 hard
//     volumes, defaults, at both sizes.
//   reference-64: the Embree oracle at 64 rays per pixel over the sphere light, 640x427.
// The claim "the full soft-shadow frame is at least 50x faster than the oracle at 64 rays" is the
// ratio of the reference-64 frame time to a wedge frame time of the same run
// (bench/summarize.py prints it; bench/README.md quotes it with the machine).
//
// Counters: fps, frame_ms, <pass>_ms (Stats::time_ms summed per frame, averaged over
// iterations), and the frame's exact work counters: z_reads, stencil_writes, penumbra_tests,
// penumbra_inside, tiles_tested, tiles_culled, tiles_accepted, wedges.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "bench_scenes.h"
#include "render/frame.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"
#include "shadows/wedge/wedge_technique.h"
#include "timed_frames.h"

namespace penumbra {
namespace {

void softShadowFrame(benchmark::State& state, const std::string& scene_name, int width, int height,
                     const TechniqueConfig& technique) {
  const Scene& scene = benchScene(scene_name);
  FrameOptions options;
  options.width = width;
  options.height = height;
  options.technique = technique;
  // Prepared once, as a viewer renders frame after frame (the oracle's BVH is per scene).
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  if (!timeWarmFrames(state, renderer, frame)) return;
  const double fps = state.counters["fps"];
  const Stats& c = frame.total;
  state.counters["z_reads"] = double(c.z_reads);
  state.counters["stencil_writes"] = double(c.stencil_writes);
  state.counters["penumbra_tests"] = double(c.penumbra_tests);
  state.counters["penumbra_inside"] = double(c.penumbra_inside);
  state.counters["tiles_tested"] = double(c.tiles_tested);
  state.counters["tiles_culled"] = double(c.tiles_culled);
  state.counters["tiles_accepted"] = double(c.tiles_accepted);
  state.counters["wedges"] = double(c.wedges);
  if (c.rays > 0) state.counters["rays"] = double(c.rays);
  state.SetLabel(fmt::format("{} {}x{}, {}: {:.1f} fps", scene_name, width, height,
                             technique.describe(), fps));
}

bool registerWedgeBenchmarks() {
  struct Case {
    std::string id;
    int width, height;
    TechniqueConfig technique;
    double min_time;
  };
  std::vector<Case> cases;
  for (const char* name : {"wedge-3pass", "wedge-1pass"}) {
    const std::string id = name;
    TechniqueConfig wedge(name);
    WedgeOptions& o = wedge.options<WedgeOptions>();
    o.cull = CullMode::Full;
    // The default culling tiles (16x16, wedge_technique.h), then 8x8, the papers' usual choice.
    cases.push_back({id, 640, 427, wedge, 0.3});
    cases.push_back({id, 1920, 1080, wedge, 0.3});
    o.tile_level = 3;
    cases.push_back({id + "-tile8", 640, 427, wedge, 0.3});
    cases.push_back({id + "-tile8", 1920, 1080, wedge, 0.3});
    // The papers' umbra pass, every pixel depth-tested and written: the A/B of the two-level
    // stencil (WedgeOptions::two_level_stencil) in the same run.
    o.tile_level = WedgeOptions{}.tile_level;
    o.two_level_stencil = false;
    cases.push_back({id + "-one-level", 640, 427, wedge, 0.3});
    cases.push_back({id + "-one-level", 1920, 1080, wedge, 0.3});
  }
  // The coverage soft shadow volumes (2003; exact per-edge coverage) and Heckbert-Herf (16 hard
  // volumes averaged), defaults, on the same frames: their ratio to wedge-3pass of the same run.
  for (const char* name : {"coverage", "heckbert-herf"}) {
    cases.push_back({name, 640, 427, TechniqueConfig(name), 0.3});
    cases.push_back({name, 1920, 1080, TechniqueConfig(name), 0.3});
  }
  TechniqueConfig oracle("reference");
  oracle.options<ReferenceOptions>().rays = 64;
  // Slow (bench/README.md): few iterations per repetition; rounds give the spread.
  cases.push_back({"reference-64", 640, 427, oracle, 0.5});
  for (const Case& c : cases) {
    const std::string name =
        fmt::format("SoftShadowFrame/columns/{}x{}/{}", c.width, c.height, c.id);
    benchmark::RegisterBenchmark(
        name.c_str(),
        [c](benchmark::State& s) { softShadowFrame(s, "columns", c.width, c.height, c.technique); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinWarmUpTime(0.05)
        ->MinTime(c.min_time);
  }
  return true;
}

const bool wedge_registered = registerWedgeBenchmarks();

}  // namespace
}  // namespace penumbra
