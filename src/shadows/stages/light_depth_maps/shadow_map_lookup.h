#pragma once
// The per-pixel half of a shadow map, shared by `shadow-map` and `pcss`: for every visible point
// that faces the light, its projection into the light's depth maps (moved off its surface first
// by the normal offset), the receiver's slope for the bias, and the stencil limit
// (light_frustum_stencil.h) that skips points outside the spot.
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

// The unit normal of the visible triangle, on the side of the light (0 for a degenerate one).
dvec3 receiverNormal(const Scene& scene, uint32_t primitive, const dvec3& p, const dvec3& light);

// +1 where the eye sees the side of the plane through p that n points to, else -1.
inline double eyeSide(const dvec3& n, const dvec3& p, const dvec3& eye) {
  return glm::dot(n, eye - p) >= 0.0 ? 1.0 : -1.0;
}

// tan(angle between the receiver's normal n and the direction from p to the light), which
// scales the slope bias: a plane's depth in the map changes by this many texels per texel.
// Unbounded at grazing angles; capped at kMaxSlope, where the point is almost on its own
// terminator and the facing test of resolveVisibility takes over.
inline constexpr double kMaxSlope = 10.0;
double receiverSlope(const dvec3& n, const dvec3& p, const dvec3& light);

// Normal-offset sampling (Urho3D's BiasParameters::normalOffset_ does the same; Unity's
// Light.shadowNormalBias, also in texels, moves the casters inward along their normals instead,
// which docs/shadow-maps.md compares): the point is looked up `texels` x the texel's world size
// at its distance away from its surface, along its normal n. A plane at angle t to the light
// then lies texels / cos(t) behind the moved point along the light's ray, and rises by tan(t)
// per texel of the map: the moved point stays in front of its own plane for lookups up to
// texels / sin(t) >= texels away, at every angle, where a depth bias for the same must grow
// without bound at grazing angles. The price: the lookup moves sideways by up to `texels`
// texels, which shifts shadow boundaries on surfaces at grazing angles by as much. Returns the
// point unchanged for texels = 0.
dvec3 offsetAlongNormal(const LightDepthMaps& maps, const dvec3& p, const dvec3& n,
                        const MapPoint& m, double texels);

// The receiver's plane as the map sees it: the surface point that a texel dx, dy texels from
// the looked-up point's projection shows at distance d along the face's axis lies
//   height(d, dx, dy) = a + d * (step_x * dx + step_y * dy - a / w)
// above the plane through the looked-up point with normal n (world units). Exact, not a
// linearisation: that point is centre + d * D(s) for the texel position s, and D is affine in s
// (light_depth_maps.cpp draws each face with a lookAt view and a square perspective). `pcss
// --occluder-test plane` counts a sample as an occluder only where this height exceeds its
// constant bias, so a planar receiver never finds itself, at any angle: the receiver-plane test
// of receiver-plane depth bias, done in world space.
struct ReceiverPlane {
  double a = 0;                // n . (light centre - point): the light centre's height
  double step_x = 0, step_y = 0;
};
ReceiverPlane receiverPlane(const LightDepthMaps& maps, int face, const dvec3& point,
                            const dvec3& n);

// The points of one row of the eye buffers that land on one face of the maps, for a lookup
// kernel (map_lookup_kernel.h): the per-point arrays are padded with harmless points (at the
// face's centre, w = 0, slope 0; their answers are dropped and pcss counts no reads for them)
// to a multiple of kLookupBlock; x holds the real points' pixels.
struct LookupBatch {
  int face = 0, y = 0;
  std::vector<int> x;
  std::vector<double> sx, sy, w, slope;  // MapPoint's, clamped by clampLookupPosition
  std::vector<double> plane_a, plane_x, plane_y;  // the ReceiverPlane's a, step_x, step_y
  // The light centre's height above the receiver's plane on the side the eye sees (negative:
  // behind it, for a point whose plane cuts the light with the centre on the far side).
  std::vector<double> light_height;
  size_t count() const { return x.size(); }
  size_t padded() const { return sx.size(); }
  void clear();
  void add(int pixel_x, const MapPoint& m, double receiver_slope, const ReceiverPlane& plane,
           double height, int size);
  void pad(int size);
};

// Writes `visibility` (sized like the eye buffers): 1 on the background, 0 where the visible
// triangle faces away from the light (resolveVisibility's rules), 0 for a spotlight's points
// outside its frustum, else what `lookup(batch, values)` writes to values[k] for the k-th point
// of `batch`: the row's visible points that land on one face, batched for a kernel. With
// `limit` (a lightFrustumStencil of the spot), pixels it does not hold are not looked up: they
// get what a point outside the frustum gets (0 for a spotlight; a fitted spot holds every
// visible point, so none). Counts shadow_map_lookups (pixels looked up) and lookups_saved
// (pixels the limit skipped). Each point is looked up where offsetAlongNormal moves it by
// `normal_offset` texels (0: at the point itself); whether a spotlight reaches it is decided at
// the point itself. Rows run in parallel; each row's answers depend on that row only.
template <class Lookup>
void lookupVisiblePoints(const Scene& scene, const Light& light, const View& view,
                         const EyeBuffers& eye, const LightDepthMaps& maps,
                         const Image<int32_t>* limit, double normal_offset,
                         Image<float>& visibility, Stats& stats, Lookup&& lookup) {
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
      const dvec3 n = receiverNormal(scene, id, p, centre);
      const dvec3 q = offsetAlongNormal(maps, p, n, m, normal_offset);
      MapPoint moved = q == p ? m : maps.project(q);
      // Moved onto or past the light centre (a light almost touching the surface): p itself.
      const bool keep = moved.w > 0.0;
      if (!keep) moved = m;
      batches[size_t(moved.face)].add(
          x, moved, receiverSlope(n, p, centre), receiverPlane(maps, moved.face, keep ? q : p, n),
          eyeSide(n, p, dvec3(view.eye)) * glm::dot(n, centre - p), maps.size);
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
