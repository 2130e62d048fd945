#pragma once
// The per-pixel half of a shadow map, shared by `shadow-map` and `pcss`: for every visible point
// that faces the light, its projection into the light's depth maps, the receiver's slope for the
// bias, and the stencil limit (light_frustum_stencil.h) that skips points outside the spot.
#include <cstdint>
#include <utility>
#include <vector>

#include "core/image.h"
#include "core/parallel.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/stages/light_depth_maps/light_depth_maps.h"
#include "shadows/stages/light_depth_maps/lookup_counters.h"
#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"
#include "shadows/stages/silhouettes/facing_away.h"

namespace penumbra {

// tan(angle between the visible triangle's normal and the direction from p to the light),
// which scales the slope bias: a plane's depth in the map changes by this many texels per
// texel. Unbounded at grazing angles; capped at kMaxSlope, where the point is almost on its own
// terminator and the facing test of resolveVisibility takes over.
inline constexpr double kMaxSlope = 10.0;
double receiverSlope(const Scene& scene, uint32_t primitive, const dvec3& p, const dvec3& light);

// The points of one row of the eye buffers that land on one face of the maps, for a lookup
// kernel (map_lookup_kernel.h): the per-point arrays are padded with harmless points (at the
// face's centre, w = 0, slope 0; their answers are dropped and pcss counts no reads for them)
// to a multiple of kLookupBlock; x holds the real points' pixels.
struct LookupBatch {
  int face = 0, y = 0;
  std::vector<int> x;
  std::vector<double> sx, sy, w, slope;  // MapPoint's, clamped by clampLookupPosition
  size_t count() const { return x.size(); }
  size_t padded() const { return sx.size(); }
  void clear();
  void add(int pixel_x, const MapPoint& m, double receiver_slope, int size);
  void pad(int size);
};

// Writes `visibility` (sized like the eye buffers): 1 on the background, 0 where the visible
// triangle faces away from the light (resolveVisibility's rules), 0 for a spotlight's points
// outside its frustum, else what `lookup(batch, values)` writes to values[k] for the k-th point
// of `batch`: the row's visible points that land on one face, batched for a kernel. With
// `limit` (a lightFrustumStencil of the spot), pixels it does not hold are not looked up: they
// get what a point outside the frustum gets (0 for a spotlight; a fitted spot holds every
// visible point, so none). Counts shadow_map_lookups (pixels looked up) and lookups_saved
// (pixels the limit skipped). Rows run in parallel; each row's answers depend on that row only.
template <class Lookup>
void lookupVisiblePoints(const Scene& scene, const Light& light, const View& view,
                         const EyeBuffers& eye, const LightDepthMaps& maps,
                         const Image<int32_t>* limit, Image<float>& visibility, Stats& stats,
                         Lookup&& lookup) {
  const dvec3 centre(light.center);
  const float outside = maps.frustums.spotlight ? 0.0f : 1.0f;
  const int width = eye.primitive.width(), height = eye.primitive.height();
  visibility.resizeForOverwrite(width, height);
  const FacingAway away(scene, light, view);
  std::vector<uint64_t> done(size_t(height), 0), saved(size_t(height), 0);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    const uint32_t* ids = eye.primitive.row(y);
    float* out = visibility.row(y);
    std::vector<LookupBatch> batches(maps.depth.size());
    for (size_t f = 0; f < batches.size(); ++f) {
      batches[f].face = int(f);
      batches[f].y = y;
    }
    for (int x = 0; x < width; ++x) {
      const uint32_t id = ids[x];
      if (id == kNoPrimitive) {
        out[x] = 1.0f;
        continue;
      }
      if (away(id)) {
        out[x] = 0.0f;
        continue;
      }
      if (limit != nullptr && limit->at(x, y) <= 0) {
        ++saved[row];
        out[x] = outside;
        continue;
      }
      ++done[row];
      const dvec3 p = view.unproject(x, y, eye.depth.depth.at(x, y));
      const MapPoint m = maps.project(p);
      if (!(m.w > 0.0)) {
        out[x] = 1.0f;  // at the light centre itself
        continue;
      }
      if (!m.inside && maps.frustums.spotlight) {
        out[x] = 0.0f;
        continue;
      }
      batches[size_t(m.face)].add(x, m, receiverSlope(scene, id, p, centre), maps.size);
    }
    std::vector<float> values;
    for (LookupBatch& batch : batches) {
      if (batch.count() == 0) continue;
      batch.pad(maps.size);
      values.resize(batch.padded());
      lookup(std::as_const(batch), values.data());
      for (size_t k = 0; k < batch.count(); ++k) out[batch.x[k]] = values[k];
    }
  });
  uint64_t looked_up = 0, skipped = 0;
  for (const uint64_t n : done) looked_up += n;
  for (const uint64_t n : saved) skipped += n;
  stats.count(kShadowMapLookups, looked_up);
  stats.count(kLookupsSaved, skipped);
}

}  // namespace penumbra
