#include "raster/eye_pass.h"

#include <algorithm>
#include <utility>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/occlusion_culler.h"
#include "raster/rasterizer.h"

namespace penumbra {

EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats, bool simd,
                         OcclusionCuller* occlusion) {
  return renderEyePass(scene, view, stats, DepthPassOptions{.simd = simd}, occlusion);
}

EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats,
                         const DepthPassOptions& options, OcclusionCuller* occlusion) {
  PassTimer timer(stats, "eye");
  ClipTriangles tris;
  tris.clip.resize(scene.meshes.empty() ? 0 : [&] {
    size_t n = 0;
    for (const Mesh& m : scene.meshes) n += m.positions.size();
    return n;
  }());
  const size_t triangle_count = occlusion != nullptr ? 0 : scene.triangleCount();
  // Every triangle as the mesh has it, its global id as its payload: filled in parallel (a
  // dense mesh's few hundred thousand triangles were a serial stretch of the frame). With
  // occlusion culling, only the triangles the culler cannot prove hidden, in the same order.
  tris.indices.resize(triangle_count * 3);
  tris.payload.resize(triangle_count);
  // No flags (empty: 0 for every triangle), so no back-face culling, not even for closed
  // meshes: the stored depth must be the closest of every triangle, because shadow-volume light
  // caps are those same triangles drawn again with bit-identical depth. A culled back face can
  // round a hair closer than the front face at an eye silhouette, and z-fail would then see a
  // cap in front of the visible point, breaking the identity z-pass == z-fail.
  EyeBuffers eye;
  eye.mesh_vertex_base.reserve(scene.meshes.size());
  size_t base = 0;
  uint32_t global_id = 0;
  for (const Mesh& mesh : scene.meshes) {
    eye.mesh_vertex_base.push_back(uint32_t(base));
    // Computed once for the frame: shadow volumes and wedges draw their finite vertices from
    // these (EyeBuffers::clip_vertices), so a light cap lands on bit-identical coordinates.
    // Every vertex, culled or not: the techniques read them all.
    parallelFor((mesh.positions.size() + 4095) / 4096, [&](size_t chunk) {
      const size_t end = std::min(mesh.positions.size(), (chunk + 1) * 4096);
      for (size_t i = chunk * 4096; i < end; ++i)
        tris.clip[base + i] = view.toClip(vec4(mesh.positions[i], 1.0f));
    });
    const size_t first = global_id, count = occlusion != nullptr ? 0 : mesh.triangleCount();
    parallelFor((count + 16383) / 16384, [&](size_t chunk) {
      const size_t end = std::min(count, (chunk + 1) * 16384);
      for (size_t t = chunk * 16384; t < end; ++t) {
        for (size_t k = 0; k < 3; ++k)
          tris.indices[(first + t) * 3 + k] = uint32_t(base + mesh.indices[t * 3 + k]);
        tris.payload[first + t] = int32_t(first + t);
      }
    });
    global_id += uint32_t(mesh.triangleCount());
    base += mesh.positions.size();
  }
  if (occlusion != nullptr)
    occlusion->selectTriangles(view, tris.clip, tris, stats, options.simd);
  // rasterizeDepth writes every pixel, background included.
  eye.depth.depth.resizeForOverwrite(view.width, view.height);
  eye.primitive.resizeForOverwrite(view.width, view.height);
  rasterizeDepth(tris, eye.depth, eye.primitive, stats, options);  // tile ranges included
  if (occlusion != nullptr) occlusion->track(view, eye.depth, eye.primitive);
  eye.clip_vertices = std::move(tris.clip);
  return eye;
}

}  // namespace penumbra
