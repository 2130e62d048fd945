#include "shadows/stages/light_sampling/ray_origin.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "raster/depth_buffer.h"

namespace penumbra {
namespace {

// Origins leave their triangle by this fraction of (largest coordinate + longest edge): 16x
// float32 rounding (2^-24), the scale of the float ray origin's rounding and of Embree's float
// intersection tests against the triangle and its coplanar neighbours.
constexpr double kSurfaceOffset = 16.0 * 0x1.0p-24;

// Without a triangle to put the point on, it steps this many pixel footprints toward the eye:
// 3x the largest depth-buffer error measured (see RayOrigins::start).
constexpr double kFallbackFootprints = 0.125;

// A visible triangle whose closest point is farther than this many pixel footprints from p
// does not hold p (the eye buffers disagree with each other): 25x the largest error measured.
constexpr double kMaxSnapFootprints = 1.0;

double magnitude(const dvec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Moves q, a point of triangle t, to at least eps inside each edge, perpendicular to the edges
// it is closer to than that: a point on an edge lies in the plane of a neighbour meeting the
// triangle at 90 degrees (an inside corner), and a ray from there would hit that neighbour at
// t = 0 whichever way it went. Points farther inside stay put.
dvec3 awayFromEdges(dvec3 q, const OriginTriangle& t, double eps) {
  if (t.length / t.perimeter <= eps) return (t.a + t.b + t.c) / 3.0;  // inradius <= eps
  const dvec3 corners[3] = {t.a, t.b, t.c};
  for (int i = 0; i < 3; ++i) {
    const double distance = glm::dot(q - corners[i], t.inward[i]);
    if (distance < eps) q += t.inward[i] * (eps - distance);
  }
  return q;
}

}  // namespace

void RayOrigins::checkPrimitiveIds(const Image<uint32_t>& ids) const {
  for (size_t i = 0; i < ids.size(); ++i) {
    const uint32_t id = ids[i];
    PENUMBRA_CHECK(id == kNoPrimitive || id < triangleCount(),
                   "eye pixel {} names triangle {} but the scene has {} triangles", i, id,
                   triangleCount());
  }
}

dvec3 closestPointOnTriangle(const dvec3& q, const dvec3& a, const dvec3& b, const dvec3& c) {
  // Voronoi regions of the vertices, then of the edges, else the face (barycentric).
  const dvec3 ab = b - a, ac = c - a, aq = q - a;
  const double d1 = glm::dot(ab, aq), d2 = glm::dot(ac, aq);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const dvec3 bq = q - b;
  const double d3 = glm::dot(ab, bq), d4 = glm::dot(ac, bq);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const dvec3 cq = q - c;
  const double d5 = glm::dot(ab, cq), d6 = glm::dot(ac, cq);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

RayOrigins::RayOrigins(const Scene& scene, const View& view)
    : scene_(scene), view_(view),
      pixel_angle_(2.0 / (double(view.projection[1][1]) * view.height)) {
  // Ids number triangles mesh after mesh in Scene::meshes order; the offsets are rebuilt from
  // the meshes so the oracle does not depend on Scene::triangle_offsets having been filled.
  offsets_.reserve(scene.meshes.size() + 1);
  uint64_t total = 0;
  for (const Mesh& mesh : scene.meshes) {
    offsets_.push_back(total);
    total += mesh.triangleCount();
  }
  offsets_.push_back(total);
}

// p comes from the depth buffer, so it is on its triangle only up to the eye pass's errors:
// the rasterizer snaps vertices to 1/16 pixel for coverage (its depth planes come from the
// unsnapped vertices) and interpolates depth in float. Measured over
// grazing planes, spheres, a fractal terrain and close-up boxes at 640x427 and 1280x854, p is
// up to 0.037 pixel footprints (distance * pixel_angle) off the triangle's plane, and can lie
// a similar distance beyond one of its edges, over the neighbouring triangle. Offsetting p by
// more than that error (the usual fix) moves the shaded point: it shifts penumbrae (a mean
// bias of 0.02 in visibility on the analytic disk test at half a footprint) and leaks light
// into creases whose neighbouring facet does shadow the point. So p is replaced by the closest
// point of its triangle (in double: on the plane and inside the edges, a move no larger than
// the eye pass's own error) and lifted off it, and off its edges, only by the float
// arithmetic's scale. Beside a convex edge the neighbour lies behind the triangle's plane,
// which the rays leave; beside a concave one (a valley, an inside corner) the origin is in
// front of the neighbour's plane too, for any angle short of folding flat onto the triangle.
// A triangle that does not hold p (a degenerate one, one seen exactly edge-on, or ids that
// disagree with the depth) falls back to stepping p toward the eye by kFallbackFootprints.
void RayOrigins::deriveTriangle(uint32_t primitive, OriginTriangle& t) const {
  const size_t mesh =
      size_t(std::upper_bound(offsets_.begin(), offsets_.end(), uint64_t(primitive)) -
             offsets_.begin()) - 1;
  const Mesh& m = scene_.meshes[mesh];
  const size_t triangle = size_t(primitive - offsets_[mesh]);
  t.primitive = primitive;
  t.a = dvec3(m.vertex(triangle, 0));
  t.b = dvec3(m.vertex(triangle, 1));
  t.c = dvec3(m.vertex(triangle, 2));
  t.winding_normal = glm::cross(t.b - t.a, t.c - t.a);
  t.eye_side = glm::dot(t.winding_normal, dvec3(view_.eye) - t.a);
  t.length = glm::length(t.winding_normal);
  const double ab = glm::length(t.b - t.a), bc = glm::length(t.c - t.b);
  const double ca = glm::length(t.a - t.c);
  t.extent = std::max({ab, ca, bc});
  t.perimeter = ab + bc + ca;
  const dvec3 corners[3] = {t.a, t.b, t.c};
  for (int i = 0; i < 3; ++i) {
    // In-plane normal of edge i -> i + 1, pointing into the triangle (the vertices are
    // counter-clockwise about the winding normal, so n x edge points inward).
    t.inward[i] = glm::normalize(glm::cross(t.winding_normal, corners[(i + 1) % 3] - corners[i]));
  }
}

RayStart RayOrigins::start(int x, int y, float depth, uint32_t primitive,
                           OriginTriangle& t) const {
  const dvec3 p = view_.unproject(x, y, depth);
  const dvec3 eye(view_.eye);
  const dvec3 to_eye = eye - p;
  const double distance = glm::length(to_eye);
  const double footprint = distance * pixel_angle_;
  RayStart start;
  start.depth_point = p;
  if (primitive != kNoPrimitive && primitive < triangleCount()) {
    if (t.primitive != primitive) deriveTriangle(primitive, t);
    const dvec3 on_surface = closestPointOnTriangle(p, t.a, t.b, t.c);
    // Degenerate triangles and triangles seen exactly edge-on have no usable plane.
    if (t.length > 0.0 && t.eye_side != 0.0 && std::isfinite(t.eye_side) &&
        glm::length(on_surface - p) <= kMaxSnapFootprints * footprint) {
      const dvec3 normal = t.eye_side < 0.0 ? -t.winding_normal : t.winding_normal;
      const double eps = kSurfaceOffset * (magnitude(on_surface) + t.extent);
      const dvec3 origin = awayFromEdges(on_surface, t, eps);
      start.plane_point = t.a;
      start.plane_normal = normal;
      start.origin = origin + normal * (eps / t.length);
      return start;
    }
  }
  const double eps = std::max(kFallbackFootprints * footprint, kSurfaceOffset * magnitude(p));
  start.origin = p + to_eye * (eps / std::max(distance, 1e-300));
  return start;
}

}  // namespace penumbra
