// Whole frames and single techniques.
//
// HardShadowFrame/<scene>/<size>: a FrameRenderer's warm frame (timed_frames.h) with shadow
// volumes (VolumeMode::Auto): eye pass, silhouettes and volumes per light, stencil resolve,
// shading. This is the frame the llvmpipe peer (bench/peer/) renders with GL z-fail stencil
// volumes; bench/run_benchmarks.sh quotes the ratio of the two fps.
//
// HardShadowFrame/<scene>/<size>/hierarchical-volume: the same frame with `hierarchical-volume`
// (the same image; per-pixel work only in tiles a volume's boundary crosses), beside it.
//
// Technique/columns/640x427/<technique>: renderShadows alone for every light, on an eye pass
// rendered once outside the loop, so techniques compare on the same basis (the oracle at 1 and
// 64 rays here; soft-shadow techniques are compared against Technique/.../reference-64).
//
// Counters: fps (frames or technique runs per wall-clock second), <pass>_ms (Stats::time_ms,
// same-named passes summed per frame, averaged over iterations), and the frame's work counters.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "core/parallel.h"
#include "raster/eye_pass.h"
#include "render/frame.h"
#include "shadows/mask_options.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"
#include "timed_frames.h"

namespace penumbra {
namespace {

// Sums Stats::time_ms per pass name over every iteration, keeping the first-seen order so the
// counters read in pipeline order in the console.
class PassTimes {
 public:
  void add(const Stats& stats) {
    for (const auto& [name, ms] : stats.time_ms) {
      auto it = index_.find(name);
      if (it == index_.end()) {
        it = index_.emplace(name, totals_.size()).first;
        totals_.emplace_back(name, 0.0);
      }
      totals_[it->second].second += ms;
    }
  }
  void report(benchmark::State& state) const {
    const double n = double(state.iterations());
    for (const auto& [name, ms] : totals_) state.counters[name + "_ms"] = ms / n;
  }

 private:
  std::map<std::string, size_t> index_;
  std::vector<std::pair<std::string, double>> totals_;
};

void hardShadowFrame(benchmark::State& state, const std::string& scene_name, int width,
                     int height, const std::string& technique = "volume") {
  const Scene& scene = benchScene(scene_name);
  FrameOptions options;
  options.width = width;
  options.height = height;
  options.technique = TechniqueConfig(technique);
  // Prepared once and rendering into one kept FrameResult, as the peer keeps its buffers,
  // programs and framebuffer across frames (bench/peer/peer_renderer.cpp): both time the
  // frame loop's work, neither the scene's upload.
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  if (!timeWarmFrames(state, renderer, frame)) return;
  const double fps = state.counters["fps"];
  const Stats& last = frame.total;
  state.counters["scene_triangles"] = double(scene.triangleCount());
  // Set up for rasterization after clipping, eye pass and volumes together.
  state.counters["triangles"] = double(last.triangles);
  state.counters["pixels_rasterized"] = double(last.pixels_rasterized);
  state.counters["silhouette_edges"] = double(last.silhouette_edges);
  state.counters["tiles_culled"] = double(last.tiles_culled);
  state.counters["threads"] = double(workerCount());
  if (technique != "volume") {
    state.counters["z_reads"] = double(last.z_reads);
    state.counters["stencil_writes"] = double(last.stencil_writes);
    state.counters["tiles_boundary"] = double(last.counter("tiles_boundary"));
  }
  state.SetLabel(fmt::format("{} {}x{} {} tris {} lights, {} (auto): {:.1f} fps", scene_name,
                             width, height, scene.triangleCount(), scene.lights.size(), technique,
                             fps));
}

void technique(benchmark::State& state, const std::string& scene_name, int width, int height,
               const TechniqueConfig& config) {
  const Scene& scene = benchScene(scene_name);
  const View view = scene.camera.makeView(width, height);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  // Per-scene state (the oracle's BVH) is prepared once, as a frame loop does.
  const std::unique_ptr<PreparedTechnique> prepared = prepareTechnique(config, scene);
  renderUntimed(*prepared, scene, view, eye);
  PassTimes passes;
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
    passes.add(frame);
    last = std::move(frame);
  }
  if (seconds <= 0.0) return;
  const double per_second = double(state.iterations()) / seconds;
  state.counters["fps"] = per_second;
  state.counters["technique_ms"] = 1e3 / per_second;
  passes.report(state);
  if (last.rays > 0) {
    state.counters["rays"] = double(last.rays);
    state.counters["Mrays/s"] = double(last.rays) * per_second * 1e-6;
  }
  state.counters["pixels_rasterized"] = double(last.pixels_rasterized);
  state.counters["threads"] = double(workerCount());
  state.SetLabel(fmt::format("{} {}x{} {} lights, {}: {:.1f} ms", scene_name, width, height,
                             scene.lights.size(), config.describe(), 1e3 / per_second));
}

benchmark::internal::Benchmark* timed(benchmark::internal::Benchmark* b, double min_time) {
  return b->Unit(benchmark::kMillisecond)->UseRealTime()->MinWarmUpTime(0.05)->MinTime(min_time);
}

bool registerFrameBenchmarks() {
  struct Size {
    int width, height;
  };
  for (const char* scene : {"columns", "spheres", "fractal"}) {
    for (const Size size : {Size{640, 427}, Size{1920, 1080}}) {
      const std::string name =
          fmt::format("HardShadowFrame/{}/{}x{}", scene, size.width, size.height);
      timed(benchmark::RegisterBenchmark(name.c_str(),
                                         [scene = std::string(scene), size](benchmark::State& s) {
                                           hardShadowFrame(s, scene, size.width, size.height);
                                         }),
            0.3);
      timed(benchmark::RegisterBenchmark((name + "/hierarchical-volume").c_str(),
                                         [scene = std::string(scene), size](benchmark::State& s) {
                                           hardShadowFrame(s, scene, size.width, size.height,
                                                           "hierarchical-volume");
                                         }),
            0.3);
    }
  }

  struct TechniqueCase {
    std::string id;
    TechniqueConfig config;
    double min_time;
  };
  std::vector<TechniqueCase> cases;
  {
    cases.push_back({"volume", TechniqueConfig("volume"), 0.3});
    TechniqueConfig hard("reference");
    hard.options<ReferenceOptions>().hard = true;
    cases.push_back({"reference-hard", hard, 0.3});
    // 64 rays are slow (bench/README.md): few iterations per repetition are enough, the rounds
    // of bench/run_benchmarks.sh give the spread.
    TechniqueConfig soft("reference");
    soft.options<ReferenceOptions>().rays = 64;
    cases.push_back({"reference-64", soft, 0.5});
    // Roettger et al.'s shadow masks (docs/reproducing-hsv-and-masks.md): alpha, colour, and the
    // alpha mask at half and quarter resolution.
    cases.push_back({"mask-alpha", TechniqueConfig("mask-alpha"), 0.3});
    cases.push_back({"mask-colour", TechniqueConfig("mask-colour"), 0.3});
    for (const int scale : {2, 4}) {
      TechniqueConfig low("mask-alpha");
      low.options<MaskOptions>().scale = scale;
      cases.push_back({fmt::format("mask-alpha-1/{}", scale), low, 0.3});
    }
  }
  for (const TechniqueCase& c : cases) {
    const std::string name = fmt::format("Technique/columns/640x427/{}", c.id);
    timed(benchmark::RegisterBenchmark(name.c_str(),
                                       [config = c.config](benchmark::State& s) {
                                         technique(s, "columns", 640, 427, config);
                                       }),
          c.min_time);
  }
  // Shadow maps beside the volume techniques, in the same run (issue 12): the standard map,
  // PCSS and the alias-free map with their defaults, the hard volumes and the wedges, on
  // `columns` and `fractal` at the papers' size and at 1080p.
  for (const char* scene : {"columns", "fractal"}) {
    for (const Size size : {Size{640, 427}, Size{1920, 1080}}) {
      for (const char* id : {"volume", "depth-bounds-volume", "hierarchical-volume", "wedge-3pass",
                             "shadow-map", "pcss", "alias-free"}) {
        const std::string name =
            fmt::format("ShadowMapPeers/{}/{}x{}/{}", scene, size.width, size.height, id);
        timed(benchmark::RegisterBenchmark(
                  name.c_str(),
                  [scene = std::string(scene), size, id = std::string(id)](benchmark::State& s) {
                    technique(s, scene, size.width, size.height, TechniqueConfig(id));
                  }),
              0.3);
      }
    }
  }
  return true;
}

const bool frame_registered = registerFrameBenchmarks();

}  // namespace
}  // namespace penumbra
