#pragma once
// The per-pixel half of a shadow map, shared by `shadow-map` and `pcss`: for every visible point
// that faces the light, its projection into the light's depth maps, the receiver's slope for the
// bias, and the stencil limit (light_frustum_stencil.h) that skips points outside the spot.
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/facing_away.h"
#include "shadows/shadowmap/light_depth_maps.h"

namespace penumbra {

// tan(angle between the visible triangle's normal and the direction from p to the light),
// which scales the slope bias: a plane's depth in the map changes by this many texels per
// texel. Unbounded at grazing angles; capped at kMaxSlope, where the point is almost on its own
// terminator and the facing test of resolveVisibility takes over.
inline constexpr double kMaxSlope = 10.0;
double receiverSlope(const Scene& scene, uint32_t primitive, const dvec3& p, const dvec3& light);

// Writes `visibility` (sized like the eye buffers): 1 on the background, 0 where the visible
// triangle faces away from the light, 0 for a spotlight's points outside its frustum, else
// lookup(x, y, p, map_point, slope) for the visible point p of pixel (x, y). With `limit` (a lightFrustumStencil of
// the spot), pixels it does not hold are not looked up: they get what a point outside the
// frustum gets (0 for a spotlight; a fitted spot holds every visible point, so none). Counts
// shadow_map_lookups (pixels looked up) and lookups_saved (pixels the limit skipped).
template <class Lookup>
void lookupVisiblePoints(const Scene& scene, const Light& light, const View& view,
                         const EyeBuffers& eye, const LightDepthMaps& maps,
                         const Image<int32_t>* limit, Image<float>& visibility, Stats& stats,
                         Lookup&& lookup) {
  const dvec3 centre(light.center);
  const float outside = maps.frustums.spotlight ? 0.0f : 1.0f;
  std::vector<uint64_t> done(size_t(view.height), 0), saved(size_t(view.height), 0);
  resolveVisibility(scene, light, view, eye, visibility, [&](int x, int y) {
    if (limit != nullptr && limit->at(x, y) <= 0) {
      ++saved[size_t(y)];
      return outside;
    }
    ++done[size_t(y)];
    const dvec3 p = view.unproject(x, y, eye.depth.depth.at(x, y));
    const MapPoint m = maps.project(p);
    if (!(m.w > 0.0)) return 1.0f;  // at the light centre itself
    if (!m.inside && maps.frustums.spotlight) return 0.0f;
    return lookup(x, y, p, m, receiverSlope(scene, eye.primitive.at(x, y), p, centre));
  });
  for (const uint64_t n : done) stats.shadow_map_lookups += n;
  for (const uint64_t n : saved) stats.lookups_saved += n;
}

}  // namespace penumbra
