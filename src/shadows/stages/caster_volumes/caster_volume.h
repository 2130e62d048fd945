#pragma once
// The caster-volume stage shared by hard shadow volumes and penumbra wedges: for one caster mesh
// and one light, which triangles cast (silhouette.h), whether its volume is counted from the
// eye or from infinity, and its vertices in clip space: the finite ones are the eye pass's
// (EyeBuffers::clip_vertices), the infinite ones the same points extruded away from the light
// centre, and its caps are the casting triangles in their own vertex order.
#include <cstdint>
#include <string>

#include "core/math.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/stages/silhouettes/silhouette.h"
#include "shadows/volume_options.h"

namespace penumbra {

// True when a shadow volume cast from `light` by geometry within `caster` may contain part of
// the near-plane rectangle: the convex hull of the light and that rectangle (Lengyel's
// "occlusion pyramid") overlaps the caster's box. Conservative: false only when a separating
// plane proves the volume misses the rectangle (z-pass is only correct when the near-plane
// rectangle is outside the volume: Everitt & Kilgard 2002; thesis section 2.2).
bool mayContainNearPlane(const View& view, const vec3& light, const Bounds3& caster);

struct CasterVolume {
  Silhouette silhouette;
  bool zfail = false;      // counted from infinity
  uint32_t finite = 0;     // clip vertex of the mesh's vertex 0 (the eye pass's vertices)
  uint32_t infinite = 0;   // clip vertex of vertex 0 extruded to infinity, once appended
};

// Silhouette and z-pass / z-fail choice of scene mesh `m` for a light at `centre`. `margin`
// grows the caster's box for the near-plane test: a soft volume lies within the light's radius
// of the hard volume from the centre, so the radius keeps the test conservative for wedges.
CasterVolume casterVolume(const Scene& scene, size_t m, const EyeBuffers& eye, const vec3& centre,
                          const View& view, VolumeMode mode, CasterPolicy policy,
                          float margin = 0.0f);
// The same with mesh m's silhouette from `centre` already found (findSilhouette with the
// caller's policy), as a caller whose light has not moved keeps it.
CasterVolume casterVolume(const Scene& scene, size_t m, Silhouette silhouette,
                          const EyeBuffers& eye, const vec3& centre, const View& view,
                          VolumeMode mode, float margin = 0.0f);

// Appends every vertex of `mesh` extruded to infinity away from `centre` (homogeneous w = 0)
// to `out`, and records where vertex 0 went in volume.infinite.
void appendExtrudedVertices(const Mesh& mesh, const vec3& centre, const View& view,
                            CasterVolume& volume, ClipTriangles& out);

// Calls add(i0, i1, i2, weight) with the light cap (the casting triangle itself, weight +-1 as
// it casts) and the dark cap (the same at infinity, facing away: the negated weight) of every
// casting triangle, in triangle order. The light cap keeps the mesh's vertex order and the eye
// pass's clip vertices, so it lands bit-identically on the visible surface it comes from; a
// flip is a negated weight, never a reordering.
template <class Add>
void forEachCap(const Mesh& mesh, const CasterVolume& volume, Add&& add) {
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const int8_t o = volume.silhouette.orientation[t];
    if (o == 0) continue;
    const uint32_t a = mesh.indices[t * 3], b = mesh.indices[t * 3 + 1],
                   c = mesh.indices[t * 3 + 2];
    add(volume.finite + a, volume.finite + b, volume.finite + c, int32_t(o));
    add(volume.infinite + a, volume.infinite + b, volume.infinite + c, -int32_t(o));
  }
}

}  // namespace penumbra
