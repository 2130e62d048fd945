#pragma once
// Caster culling (docs/caster-culling.md): per light and frame, which caster meshes may shadow a
// visible point of the eye pass. A mesh whose shadow, from any point of the light, reaches none
// is left out of the silhouettes, volumes, wedges and potential edges, whole: its stencil count
// and edge events at every visible point were zero anyway, so the image is bit-identical with
// culling off (tests/test_caster_culling.cpp), only cheaper (Lloyd et al. 2004, CC shadow
// volumes; Bittner et al. 2011, shadow caster culling; Aila's 2005 thesis, section 2.2).
//
// The test, per mesh (receiver_mask.h holds the receivers):
// - X, a point of the caster at distance d from the light centre c, can shadow a receiver p
//   only by lying on a segment from p to a light point l, |l - c| <= r (r the light's bounding
//   radius, light.h). Then x' = c + t (p - c), with x = l + t (p - l), lies on the ray from c
//   through p and |x - x'| = (1 - t) |l - c| <= r: x deviates from that ray by at most
//   asin(r / d) in angle, and d <= |p - c| + r.
// - So the mesh may shadow something only if a receiver cell within its bounding cone from c,
//   widened by asin(r / d_min) (d_min: the distance from c to its bounding box), holds a
//   visible point farther than d_min - r. Small margins (kCullingAngleMargin and a relative
//   distance one) cover the rounding between the mask's unprojected points and the rasterizer's
//   depth tests.
// - Never culled: a mesh whose box comes within r of the centre (or holds it), and one whose
//   volume may contain the near plane (caster_volume.h, mayContainNearPlane, the box grown by
//   r): a z-pass count starting inside a volume counts it at every pixel.
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling_counters.h"
#include "shadows/technique.h"

namespace penumbra {

// Radians added to every caster's cone: far more than float rounding of a direction.
inline constexpr double kCullingAngleMargin = 1e-4;

struct CasterCulling {
  // Per mesh, 1 where its shadow may reach a visible point; empty when culling is off.
  std::vector<uint8_t> may_shadow;
  bool mayShadow(size_t mesh) const { return may_shadow.empty() || may_shadow[mesh] != 0; }
};

// Whether `mode` culls in this frame: Auto culls where the scene has at least as many edges as
// the view has pixels (CasterCullingMode::Auto, docs/caster-culling.md gives the measurements).
bool castersCulled(CasterCullingMode mode, const Scene& scene, const View& view);

// Which meshes of `scene` may shadow a visible point of `eye` from `light`. Where `mode` does
// not cull (castersCulled) every mesh may, and nothing is counted or timed. Otherwise adds the
// pass "caster culling" and the counters of caster_culling_counters.h to `stats`.
CasterCulling cullCasters(const Scene& scene, const Light& light, const View& view,
                          const EyeBuffers& eye, CasterCullingMode mode, Stats& stats);

// `result` with the culling's pass and counters (cullCasters' `stats`) put before its own, for
// a technique that culls and then takes a stage's result as its own.
void putCullingFirst(Stats culling, Stats& result);

}  // namespace penumbra
