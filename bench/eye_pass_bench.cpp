// Rasterizer throughput: the eye pass alone on the ~131k-triangle `fractal` scene (and on
// `spheres` for fill rate), with the SIMD tile kernels and with their scalar twins, so the SIMD
// speedup is a ratio measured in one run.
//
// Counters (per benchmark run; the JSON carries them, medians come from --benchmark_repetitions):
//   Mtri/s  triangles set up (after clipping, Stats::triangles) per wall-clock second
//   Mpix/s  (triangle, pixel) pairs inside a triangle (Stats::pixels_rasterized) per second
//   eye_ms  wall-clock milliseconds per eye pass
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "core/parallel.h"
#include "raster/eye_pass.h"

namespace penumbra {
namespace {

void eyePass(benchmark::State& state, const std::string& scene_name, int width, int height,
             bool simd) {
  const Scene& scene = benchScene(scene_name);
  const View view = scene.camera.makeView(width, height);
  Stats last;
  double seconds = 0.0;
  uint64_t triangles = 0;
  uint64_t pixels = 0;
  for (auto _ : state) {
    Stats stats;
    // Timed by hand as well as by the library: the rates below must divide by wall time, and
    // the library's rate counters divide by CPU time of the main thread only.
    const auto start = std::chrono::steady_clock::now();
    EyeBuffers eye = renderEyePass(scene, view, stats, simd);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(eye.depth.depth.data());
    triangles += stats.triangles;
    pixels += stats.pixels_rasterized;
    last = std::move(stats);
  }
  if (seconds <= 0.0) return;
  state.counters["Mtri/s"] = double(triangles) / seconds * 1e-6;
  state.counters["Mpix/s"] = double(pixels) / seconds * 1e-6;
  state.counters["eye_ms"] = seconds * 1e3 / double(state.iterations());
  state.counters["triangles"] = double(last.triangles);
  state.counters["pixels_rasterized"] = double(last.pixels_rasterized);
  state.counters["threads"] = double(workerCount());
  state.SetLabel(fmt::format("{} {}x{} {} tris {}: {:.1f} Mtri/s {:.1f} Mpix/s", scene_name,
                             width, height, scene.triangleCount(), simd ? "simd" : "scalar",
                             double(triangles) / seconds * 1e-6,
                             double(pixels) / seconds * 1e-6));
}

bool registerEyePassBenchmarks() {
  struct Case {
    const char* scene;
    int width, height;
  };
  // fractal: ~3 pixels per triangle, so it measures triangle setup and binning. spheres at
  // 1920x1080: a floor filling the screen under a few thousand triangles, so it measures fill
  // (the pixel kernels and the tile z-min/z-max build).
  for (const Case c : {Case{"fractal", 640, 427}, Case{"fractal", 1920, 1080},
                       Case{"spheres", 1920, 1080}}) {
    for (const bool simd : {true, false}) {
      const std::string name = fmt::format("EyePass/{}/{}x{}/{}", c.scene, c.width, c.height,
                                           simd ? "simd" : "scalar");
      benchmark::RegisterBenchmark(name.c_str(), [c, simd](benchmark::State& state) {
        eyePass(state, c.scene, c.width, c.height, simd);
      })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->MinWarmUpTime(0.05)
          ->MinTime(0.3);
    }
  }
  return true;
}

const bool eye_pass_registered = registerEyePassBenchmarks();

}  // namespace
}  // namespace penumbra
