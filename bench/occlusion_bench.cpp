// Object-level occlusion culling in the eye pass (docs/occlusion-culling.md): per view, the eye
// pass without culling, with culling (its culler warm: the same view drawn the iteration
// before, as in a walkthrough's next frame), and a rasterization of only the triangles visible
// in the frame (the yardstick), timed in turn in every iteration, so the three share the
// machine's state; medians over the iterations.
//
// Counters: off_ms, on_ms, visible_ms   medians of wall-clock ms per pass
//           on_over_visible              median over iterations of on / visible
//           select_ms                    median of the culler's choice alone (part of on_ms)
//           occluder_triangles           triangles drawn into the occlusion buffer
//           visible_clip_ms              median of the clip-space transform of the visible
//                                        triangles' vertices alone (part of visible_ms)
//           submitted, scene_triangles   triangles the culled pass rasterized, of the scene's
//           visible_triangles            triangles owning a pixel
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench_scenes.h"
#include "core/parallel.h"
#include "raster/eye_pass.h"
#include "raster/occlusion_culler.h"
#include "raster/rasterizer.h"
#include "scene/path.h"

namespace penumbra {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

double medianMs(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty()
             ? 0.0
             : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// The path's camera at `frame` (the scene is shared: only a copy of its camera moves).
View pathView(const Scene& scene, int frame, int width, int height) {
  if (frame < 0 || scene.path.empty()) return scene.camera.makeView(width, height);
  Scene camera_only;
  camera_only.name = scene.name;
  camera_only.camera = scene.camera;
  camera_only.lights = scene.lights;
  camera_only.path = scene.path;
  applyPathFrame(camera_only, frame);
  return camera_only.camera.makeView(width, height);
}

// The triangles owning a pixel, in id order: the pass over only the visible triangles draws
// these and transforms only their vertices.
struct VisibleSet {
  std::vector<uint32_t> ids;
};

VisibleSet visibleSet(const Image<uint32_t>& primitive, size_t triangles) {
  std::vector<uint8_t> seen(triangles, 0);
  for (size_t i = 0; i < primitive.size(); ++i)
    if (primitive[i] != kNoPrimitive) seen[primitive[i]] = 1;
  VisibleSet v;
  for (size_t t = 0; t < triangles; ++t)
    if (seen[t]) v.ids.push_back(uint32_t(t));
  return v;
}

double visiblePass(const ObjectHierarchy& h, const Scene& scene, const View& view,
                   const VisibleSet& v, double& clip_ms) {
  const auto start = std::chrono::steady_clock::now();
  ClipTriangles tris;
  tris.clip.resize(v.ids.size() * 3);
  tris.indices.resize(v.ids.size() * 3);
  tris.payload.resize(v.ids.size());
  // Vertex positions by global vertex index: mesh after mesh.
  std::vector<const vec3*> mesh_positions;
  std::vector<uint32_t> mesh_base;
  uint32_t base = 0;
  for (const Mesh& m : scene.meshes) {
    mesh_positions.push_back(m.positions.data());
    mesh_base.push_back(base);
    base += uint32_t(m.positions.size());
  }
  parallelFor((v.ids.size() + 4095) / 4096, [&](size_t chunk) {
    const size_t end = std::min(v.ids.size(), (chunk + 1) * 4096);
    for (size_t i = chunk * 4096; i < end; ++i) {
      const uint32_t t = v.ids[i];
      const uint32_t mesh = h.clusters[h.cluster_of[t]].mesh;
      for (int k = 0; k < 3; ++k) {
        const uint32_t vertex = h.vertex_indices[size_t(t) * 3 + size_t(k)] - mesh_base[mesh];
        tris.clip[i * 3 + size_t(k)] = view.toClip(vec4(mesh_positions[mesh][vertex], 1.0f));
        tris.indices[i * 3 + size_t(k)] = uint32_t(i * 3 + size_t(k));
      }
      tris.payload[i] = int32_t(t);
    }
  });
  clip_ms = msSince(start);
  DepthBuffer depth;
  depth.depth.resizeForOverwrite(view.width, view.height);
  Image<uint32_t> primitive;
  primitive.resizeForOverwrite(view.width, view.height);
  Stats stats;
  rasterizeDepth(tris, depth, primitive, stats, true);
  benchmark::DoNotOptimize(depth.depth.data());
  return msSince(start);
}

void occlusionEyePass(benchmark::State& state, const std::string& scene_name, int frame,
                      int width, int height) {
  const Scene& scene = benchScene(scene_name);
  const View view = pathView(scene, frame, width, height);
  OcclusionCuller culler(scene);
  std::vector<double> off_ms, on_ms, visible_ms, clip_ms, ratio, select_ms;
  Stats on_stats;
  VisibleSet visible;
  std::vector<vec4> clip_vertices;
  {
    Stats warm;
    const EyeBuffers eye = renderEyePass(scene, view, warm, true, &culler);
    visible = visibleSet(eye.primitive, scene.triangleCount());
    clip_vertices = eye.clip_vertices;
  }
  for (auto _ : state) {
    Stats off_stats;
    auto start = std::chrono::steady_clock::now();
    { const EyeBuffers eye = renderEyePass(scene, view, off_stats, true); }
    off_ms.push_back(msSince(start));
    on_stats = Stats{};
    start = std::chrono::steady_clock::now();
    { const EyeBuffers eye = renderEyePass(scene, view, on_stats, true, &culler); }
    on_ms.push_back(msSince(start));
    {
      // The culler's share of the culled pass: traversal, occluder batches, re-test, gathering.
      ClipTriangles out;
      Stats select_stats;
      start = std::chrono::steady_clock::now();
      culler.selectTriangles(view, clip_vertices, out, select_stats, true);
      select_ms.push_back(msSince(start));
    }
    double clip = 0.0;
    visible_ms.push_back(visiblePass(culler.hierarchy(), scene, view, visible, clip));
    clip_ms.push_back(clip);
    ratio.push_back(on_ms.back() / visible_ms.back());
  }
  state.counters["off_ms"] = medianMs(off_ms);
  state.counters["on_ms"] = medianMs(on_ms);
  state.counters["visible_ms"] = medianMs(visible_ms);
  state.counters["visible_clip_ms"] = medianMs(clip_ms);
  state.counters["select_ms"] = medianMs(select_ms);
  state.counters["occluder_triangles"] =
      double(on_stats.counter("occlusion_occluder_triangles"));
  state.counters["on_over_visible"] = medianMs(ratio);
  state.counters["off_over_on"] = medianMs(off_ms) / medianMs(on_ms);
  state.counters["submitted"] = double(on_stats.counter("occlusion_submitted_triangles"));
  state.counters["scene_triangles"] = double(scene.triangleCount());
  state.counters["visible_triangles"] = double(visible.ids.size());
  state.counters["threads"] = double(workerCount());
  state.SetLabel(fmt::format("{} frame {} {}x{}", scene_name, frame, width, height));
}

bool registerOcclusionBenchmarks() {
  struct Case {
    const char* scene;
    int frame;  // -1: the scene's camera
  };
  for (const Case c : {Case{"city", -1}, Case{"city", 10}, Case{"city", 40}, Case{"city", 80},
                       Case{"city:20", -1}, Case{"city:20", 40}, Case{"interior", -1}}) {
    const std::string name = fmt::format("OcclusionEyePass/{}/frame{}/1920x1080", c.scene, c.frame);
    benchmark::RegisterBenchmark(name.c_str(), [c](benchmark::State& state) {
      occlusionEyePass(state, c.scene, c.frame, 1920, 1080);
    })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(9);
  }
  return true;
}

const bool occlusion_registered = registerOcclusionBenchmarks();

}  // namespace
}  // namespace penumbra
