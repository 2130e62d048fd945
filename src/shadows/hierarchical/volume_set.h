#pragma once
// The shadow volumes of one point light, one closed volume per caster mesh, set up for the
// rasterizer and kept apart: the per-volume passes (depth bounds, thesis section 2.2; hierarchical
// shadow volumes, section 4.3) need to know where one volume ends and the next begins, which the
// per-pixel stencil (shadows/volume/shadow_stencil.cpp) never does.
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/volume_options.h"

namespace penumbra {

// Flag of a set-up triangle (triangle_setup.h: kZFail is 2) that is part of its closed volume
// but never drawn: the light caps of a z-pass volume, which z-pass leaves out of the count
// (volume_technique.cpp) but whose surface the tile classification must still see.
inline constexpr uint8_t kClassifyOnly = 0x80;

struct ShadowVolumeSet {
  // Every volume's triangles, volume after volume, each volume's in the order the per-pixel
  // stencil draws them: side quads of its silhouette edges, then with z-fail its caps (and
  // with z-pass its light caps, flagged kClassifyOnly, last).
  std::vector<SetupTriangle> triangles;
  // Volume v owns triangles [begin[v], begin[v + 1]).
  std::vector<uint32_t> begin;
  std::vector<uint8_t> zfail;
  // Volumes that may contain part of the near-plane rectangle, so the eye may be inside them
  // (caster_volume.h: mayContainNearPlane). Then a point nearer than all of the volume is inside
  // it too, and a z-pass volume is open on screen: no tile of it can be decided by one sample.
  std::vector<uint8_t> may_contain_eye;
  // Per volume, the depth range of its drawn triangles' vertices after clipping (reversed-Z):
  // the depth bounds of thesis section 2.2 (Figure 2.3).
  std::vector<float> depth_min, depth_max;

  size_t volumeCount() const { return zfail.size(); }
};

// Builds the volumes of every scene mesh for a point light at `centre`; fills the pass
// "silhouette" and the counters silhouette_edges and triangles of `stats`.
ShadowVolumeSet buildShadowVolumes(const Scene& scene, const vec3& centre, const View& view,
                                   const EyeBuffers& eye, VolumeMode mode, Stats& stats);

}  // namespace penumbra
