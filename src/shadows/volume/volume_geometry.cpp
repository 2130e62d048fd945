#include "shadows/volume/volume_geometry.h"

#include <algorithm>

#include "core/parallel.h"

namespace penumbra {

void appendVolumePolygons(const Mesh& mesh, const Silhouette& silhouette, const vec3& light,
                          const View& view, bool zfail, ClipTriangles& out) {
  const size_t n = mesh.positions.size();
  const uint32_t finite = uint32_t(out.clip.size());  // vertex i: finite copy
  const uint32_t infinite = uint32_t(finite + n);     // vertex i: extruded to infinity
  out.clip.resize(out.clip.size() + 2 * n);
  parallelFor((n + 4095) / 4096, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 4096);
    for (size_t i = chunk * 4096; i < end; ++i) {
      const vec3& p = mesh.positions[i];
      out.clip[finite + i] = view.toClip(vec4(p, 1.0f));
      // The point at infinity in the direction away from the light: homogeneous w = 0.
      out.clip[infinite + i] = view.toClip(vec4(p - light, 0.0f));
    }
  });
  const uint8_t flags = zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : silhouette.edges) {
    // Quad (v1, v0, v0', v1') as two triangles sharing the diagonal v1-v0'.
    out.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
    out.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
  }
  if (!zfail) return;  // z-pass: caps are never in front of a visible point (see shadow_volume.cpp)
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const int8_t o = silhouette.orientation[t];
    if (o == 0) continue;
    const uint32_t a = mesh.indices[t * 3], b = mesh.indices[t * 3 + 1], c = mesh.indices[t * 3 + 2];
    out.add(finite + a, finite + b, finite + c, o, flags);              // light cap
    out.add(infinite + a, infinite + b, infinite + c, -o, flags);       // dark cap, facing away
  }
}

}  // namespace penumbra
