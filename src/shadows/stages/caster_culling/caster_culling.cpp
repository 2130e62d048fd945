#include "shadows/stages/caster_culling/caster_culling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/parallel.h"
#include "core/timer.h"
#include "shadows/stages/caster_culling/caster_culling_counters.h"
#include "shadows/stages/caster_culling/receiver_mask.h"
#include "shadows/stages/caster_volumes/caster_volume.h"

namespace penumbra {
namespace {

// Relative slack on distances: a receiver counts as beyond the caster unless it is nearer by
// more than this fraction of the caster's distance (rounding of the unprojected points).
constexpr double kCullingDistanceMargin = 1e-4;

Bounds3 grown(Bounds3 b, float r) {
  b.min -= vec3(r);
  b.max += vec3(r);
  return b;
}

// The caster-culling test of one mesh's box (caster_culling.h).
bool boxMayShadow(const Bounds3& box, const Light& light, const View& view,
                  const ReceiverMask& mask) {
  if (box.empty()) return false;  // no vertex, no triangle: it casts nothing
  const dvec3 c(light.center);
  const double r = double(light.radius);
  const dvec3 lo(box.min), hi(box.max);
  const double nearest = glm::length(glm::clamp(c, lo, hi) - c);
  // Within the light (or holding its centre): its points have no bounded angle from the centre.
  if (!(nearest > r * (1.0 + kCullingDistanceMargin))) return true;
  if (mayContainNearPlane(view, light.center, grown(box, light.radius))) return true;
  const dvec3 axis = glm::normalize((lo + hi) * 0.5 - c);
  // The cone around `axis` through the farthest corner holds the box when it is convex (half
  // angle under 90 degrees): it holds the corners, so their convex hull. Otherwise any
  // direction may be the caster's.
  double half_angle = 0.0;
  for (int k = 0; k < 8; ++k) {
    const dvec3 corner(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    const double cos_angle = std::clamp(glm::dot(axis, glm::normalize(corner - c)), -1.0, 1.0);
    half_angle = std::max(half_angle, std::acos(cos_angle));
  }
  if (half_angle >= 0.5 * std::numbers::pi) half_angle = std::numbers::pi;
  half_angle += std::asin(std::min(1.0, r / nearest)) + kCullingAngleMargin;
  const double reach = (nearest - r) * (1.0 - kCullingDistanceMargin);
  return mask.anyFartherWithin(axis, half_angle, reach);
}

}  // namespace

bool castersCulled(CasterCullingMode mode, const Scene& scene, const View& view) {
  if (mode != CasterCullingMode::Auto) return mode == CasterCullingMode::On;
  // The receiver mask visits every pixel; culling saves work per edge of the culled casters.
  size_t edges = 0;
  for (const EdgeAdjacency& adjacency : scene.adjacency) edges += adjacency.edges.size();
  return edges >= size_t(view.width) * size_t(view.height);
}

CasterCulling cullCasters(const Scene& scene, const Light& light, const View& view,
                          const EyeBuffers& eye, CasterCullingMode mode, Stats& stats) {
  CasterCulling culling;
  if (!castersCulled(mode, scene, view)) return culling;
  PassTimer timer(stats, "caster culling");
  const ReceiverMask mask(view, eye, dvec3(light.center));
  const size_t meshes = scene.meshes.size();
  culling.may_shadow.assign(meshes, 1);
  parallelFor(meshes, [&](size_t m) {
    culling.may_shadow[m] = boxMayShadow(scene.meshes[m].bounds(), light, view, mask) ? 1 : 0;
  });
  uint64_t culled = 0, edges = 0;
  for (size_t m = 0; m < meshes; ++m) {
    if (culling.may_shadow[m]) continue;
    ++culled;
    edges += scene.adjacency[m].edges.size();
  }
  stats.count(kCastersTested, meshes);
  stats.count(kCastersCulled, culled);
  stats.count(kCulledCasterEdges, edges);
  return culling;
}

void putCullingFirst(Stats culling, Stats& result) {
  culling.add(result);
  result = std::move(culling);
}

}  // namespace penumbra
