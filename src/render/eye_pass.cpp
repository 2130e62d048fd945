#include "render/eye_pass.h"

#include <algorithm>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/rasterizer.h"

namespace penumbra {

EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats, bool simd) {
  PassTimer timer(stats, "eye");
  ClipTriangles tris;
  tris.clip.resize(scene.meshes.empty() ? 0 : [&] {
    size_t n = 0;
    for (const Mesh& m : scene.meshes) n += m.positions.size();
    return n;
  }());
  const size_t triangle_count = scene.triangleCount();
  tris.indices.reserve(triangle_count * 3);
  tris.payload.reserve(triangle_count);
  tris.flags.reserve(triangle_count);
  size_t base = 0;
  uint32_t global_id = 0;
  for (const Mesh& mesh : scene.meshes) {
    // view.toClip is the one transform every pass uses, so a triangle drawn again as a shadow
    // volume's light cap lands on bit-identical clip coordinates.
    parallelFor((mesh.positions.size() + 4095) / 4096, [&](size_t chunk) {
      const size_t end = std::min(mesh.positions.size(), (chunk + 1) * 4096);
      for (size_t i = chunk * 4096; i < end; ++i)
        tris.clip[base + i] = view.toClip(vec4(mesh.positions[i], 1.0f));
    });
    // Closed meshes only show their outside, unless the eye is inside them (then nothing of the
    // mesh is drawn, as in any renderer that culls back faces).
    const uint8_t flags = mesh.closed ? kCullBackFace : 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t, ++global_id) {
      tris.add(uint32_t(base + mesh.indices[t * 3]), uint32_t(base + mesh.indices[t * 3 + 1]),
               uint32_t(base + mesh.indices[t * 3 + 2]), int32_t(global_id), flags);
    }
    base += mesh.positions.size();
  }
  EyeBuffers eye;
  eye.depth.depth.resize(view.width, view.height, 0.0f);
  eye.primitive.resize(view.width, view.height, kNoPrimitive);
  rasterizeDepth(tris, eye.depth.depth, eye.primitive, stats, simd);
  eye.depth.buildTileRanges();
  return eye;
}

}  // namespace penumbra
