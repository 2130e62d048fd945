#include "shadows/exact/pixel_edges.h"

#include <algorithm>
#include <cmath>

#include "core/pseudo_angle.h"
#include "raster/rasterizer.h"

namespace penumbra {

CuttingPlace classifyCutting(const dvec3& a, const dvec3& b, const dvec3& c, const PixelBasis& f) {
  // The whole triangle in front (the clipped part then is too): the common case, no clipping.
  const double limit = f.light_near * (1.0 - 1e-9);
  if (std::max({glm::dot(a - f.p, f.axis), glm::dot(b - f.p, f.axis),
                glm::dot(c - f.p, f.axis)}) < limit)
    return CuttingPlace::InFront;
  // Sutherland-Hodgman against the four planes through p tangent to the cone, a little wide.
  const double sin_w = std::min(1.0, f.sin_max * (1.0 + 1e-6) + 1e-12);
  const double cos_w = std::sqrt(1.0 - sin_w * sin_w);
  dvec3 polygon[8] = {a - f.p, b - f.p, c - f.p};
  dvec3 clipped[8];
  int count = 3;
  const dvec3 sides[4] = {f.tangent, -f.tangent, f.bitangent, -f.bitangent};
  for (const dvec3& side : sides) {
    const dvec3 n = sin_w * f.axis - cos_w * side;  // inside: n . x >= 0
    int out = 0;
    for (int i = 0; i < count; ++i) {
      const dvec3& u = polygon[i];
      const dvec3& v = polygon[(i + 1) % count];
      const double du = glm::dot(n, u), dv = glm::dot(n, v);
      if (du >= 0.0) clipped[out++] = u;
      if ((du >= 0.0) != (dv >= 0.0)) clipped[out++] = u + (v - u) * (du / (du - dv));
    }
    count = out;
    if (count == 0) return CuttingPlace::Outside;
    std::copy(clipped, clipped + count, polygon);
  }
  double deepest = -1e300;
  for (int i = 0; i < count; ++i) deepest = std::max(deepest, glm::dot(polygon[i], f.axis));
  return deepest < limit ? CuttingPlace::InFront : CuttingPlace::Across;
}

bool mayBlockSamples(const CuttingTriangle& t, const PixelBasis& f, const Light& light) {
  // A relative margin far wider than the rounding of these double evaluations.
  const double scale = glm::length(f.p - dvec3(light.center)) + light.radius;
  const double margin = 1e-9 * scale;
  for (int k = 0; k < t.region_count; ++k) {
    const dvec4& plane = t.region[size_t(k)];
    if (glm::dot(dvec3(plane), f.p) + plane.w < -margin) return false;
  }
  // Wholly deeper along the axis than the light centre: behind every point of the cap seen from
  // p (whose depths are at most d - r^2 / d), so crossed only after the light. A planar light's
  // samples lie anywhere in its bounding ball, down to the ball's far depth d + r.
  const double light_far_depth = f.light_near + light.radius * (f.planar ? 2.0 : 1.0);
  if (std::min({glm::dot(t.v[0] - f.p, f.axis), glm::dot(t.v[1] - f.p, f.axis),
                glm::dot(t.v[2] - f.p, f.axis)}) > light_far_depth * (1.0 + 1e-9))
    return false;
  // The cap seen from p: sphere points q with (q - c) . u >= r^2 / d, u the unit vector from c
  // toward p; it lies in the ball around m = c + u r^2 / d of radius r sqrt(1 - r^2 / d^2).
  // A planar light: the whole bounding ball.
  const dvec3 c(light.center);
  const double r = light.radius, d = glm::length(f.p - c);
  const dvec3 m = f.planar ? c : c + (f.p - c) * (r * r / (d * d));
  const double rho = f.planar ? r : r * std::sqrt(std::max(0.0, 1.0 - r * r / (d * d)));
  const dvec3 n(t.plane);
  const double at_p = glm::dot(n, f.p) + t.plane.w, at_m = glm::dot(n, m) + t.plane.w;
  const bool same_side = at_p > 0.0 ? at_m > rho + margin : at_m < -rho - margin;
  return !same_side;
}

SampleRuns triangleRuns(const CuttingTriangle& t, const PixelBasis& f,
                        const SortedSamples& samples) {
  SampleRuns all;
  all.end[0] = uint32_t(samples.padded);
  // A planar light's samples have no fixed angle around the centre on the point's plane.
  if (f.planar) return all;
  double angle[3];
  for (int k = 0; k < 3; ++k) {
    const dvec3 v = t.v[k] - f.p;
    const double z = glm::dot(v, f.axis);
    if (!(z > f.z_min)) return all;
    angle[k] = pseudoAngle(glm::dot(v, f.tangent), glm::dot(v, f.bitangent));
  }
  std::sort(angle, angle + 3);
  // The covering arc starts after the widest gap between consecutive angles; a gap under a half
  // turn means the angles surround the centre.
  const double gaps[3] = {angle[1] - angle[0], angle[2] - angle[1], angle[0] + 4.0 - angle[2]};
  const int widest = int(std::max_element(gaps, gaps + 3) - gaps);
  if (gaps[widest] <= 2.0) return all;
  const double from = angle[(widest + 1) % 3];
  return sampleRuns(samples, from, from + (4.0 - gaps[widest]));
}

// Does o + t d, 0 < t < t_max, cross the triangle (Moller and Trumbore 1997, in double)?
bool segmentHitsTriangle(const dvec3& o, const dvec3& d, double t_max, const dvec3& a,
                         const dvec3& b, const dvec3& c) {
  const dvec3 e1 = b - a, e2 = c - a;
  const dvec3 q = glm::cross(d, e2);
  const double det = glm::dot(e1, q);
  if (det == 0.0) return false;  // the segment lies in the triangle's plane: crosses nothing
  const double inv = 1.0 / det;
  const dvec3 s = o - a;
  const double u = glm::dot(s, q) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const dvec3 r = glm::cross(s, e1);
  const double v = glm::dot(d, r) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double hit = glm::dot(e2, r) * inv;
  return hit > 0.0 && hit < t_max;
}
namespace {

// Whether p, a point of the triangle's plane up to rounding, projects into the triangle abc
// (edges included).
bool pointOnTriangle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 n = glm::cross(b - a, c - a);
  return glm::dot(glm::cross(b - a, p - a), n) >= 0.0 &&
         glm::dot(glm::cross(c - b, p - b), n) >= 0.0 &&
         glm::dot(glm::cross(a - c, p - c), n) >= 0.0;
}

}  // namespace

// Sets up the basis of a pixel; false when its visibility is already known (`known`).
bool setupPixel(int x, int y, float depth, uint32_t primitive, int32_t stencil,
                const RayOrigins& origins, const Light& light, OriginTriangle& triangle,
                bool replayed, PixelBasis& f, float& known) {
  const dvec3 c(light.center);
  const double r = light.radius;
  f.ready = true;
  f.primitive = primitive;
  f.start = origins.start(x, y, depth, primitive, triangle);
  f.planar = light.shape != LightShape::Sphere;
  f.inside_light = false;
  // A point inside a sphere light sees all of it (as the oracle has it); inside a planar
  // light's bounding ball the oracle still traces its rays, and so does the caller.
  if (glm::length(c - f.start.origin) <= r) {
    f.inside_light = f.planar;
    known = 1.0f;
    return false;
  }
  // The oracle's rays start at the float origin; every test here is made from that point.
  f.p = dvec3(vec3(f.start.origin));
  f.cone = makeSphereCone(f.start.origin, c, r);
  f.axis = dvec3(f.cone.axis);
  f.tangent = dvec3(f.cone.tangent);
  f.bitangent = dvec3(f.cone.bitangent);
  const double omc = f.cone.one_minus_cos_max;
  f.light_radius = std::sqrt(omc * (2.0 - omc)) / (1.0 - omc) * (1.0 + 1e-5);
  f.z_min = 1e-7 * glm::length(c - f.p);
  f.light_near = glm::length(c - f.p) - r;
  f.cos_max = 1.0 - omc;
  f.sin_max = std::sqrt(omc * (2.0 - omc));
  // The visible triangle, left out of the count. `replayed`: the count is moved to the origin
  // (quadCountShift, capCrossings), so it holds the triangle when the origin's segment to the
  // centre crosses it. Otherwise it is the stencil's at the depth-buffer point, which counted
  // the triangle when the centre is behind it and the point lies on it (the segment from the
  // point to the centre then starts on it; a point the rasterizer's snapping put just past one
  // of its edges is outside its volume).
  bool counted = f.start.intoSurface(c);
  if (triangle.primitive == primitive && triangle.length > 0.0) {
    if (replayed) {
      counted =
          segmentHitsTriangle(f.p, c - f.p, 1.0 - kTfarShrink, triangle.a, triangle.b, triangle.c);
    } else if (counted) {
      counted = pointOnTriangle(f.start.depth_point, triangle.a, triangle.b, triangle.c);
    }
  }
  f.centre_count = stencil - (counted ? 1 : 0);
  f.reach = 0;
  return true;
}
int32_t quadCountShift(const PotentialEdge& e, const QuadReplay& replay, int x, int y,
                       const PixelBasis& f, bool& zfail) {
  zfail = false;
  const StencilQuads& quads = replay.quads;
  // Only a quad whose plane passes by the two points can count differently at them; elsewhere
  // along the eye's ray the stencil's decision stands (its quads' borders are snapped, and a
  // border near the pixel is shared with a neighbouring quad whose decision pairs with it).
  // Tested first, from the edge alone: most candidate edges stop here. (With a z-fail volume in
  // the basis, its edges must reach centreCountShift whatever their plane: looked up first.)
  const dvec3& m = e.centre_normal;
  const double mm = glm::dot(m, m);
  const double at_point = glm::dot(m, f.p - replay.centre);
  const double at_depth_point = glm::dot(m, f.start.depth_point - replay.centre);
  const double reach2 = f.quad_reach * f.quad_reach * mm;
  const bool far = !(mm > 0.0) ||
                   (at_point * at_point > reach2 && at_depth_point * at_depth_point > reach2);
  if (far && !replay.any_zfail) return 0;
  if (size_t(e.scene_edge) + 1 >= quads.first.size()) return 0;
  const uint32_t begin = quads.first[e.scene_edge], end = quads.first[e.scene_edge + 1];
  if (begin == end) return 0;  // no quad: no silhouette from the centre, or off screen
  const SetupTriangle& any = quads.setup[quads.pieces[begin]];
  if ((any.flags & kZFail) != 0) {
    zfail = true;
    return 0;
  }
  if (far) return 0;
  int32_t stencil = 0;
  for (uint32_t k = begin; k < end; ++k) {
    stencil += stencilContributionAt(quads.setup[quads.pieces[k]], x, y, replay.eye.depth,
                                     &replay.eye.primitive);
  }
  // The quad: the points c + alpha (a - c) + beta (b - c), alpha, beta >= 0, alpha + beta >= 1.
  // A z-pass count adds the polygon's contribution where the segment from the eye to the point
  // crosses it, as the stencil does at the pixel's own point. The stencil leaves out the quads
  // of the visible triangle's edges when it faces the eye and the centre alike (owners): the
  // quad then lies behind its plane and no segment from the eye to a point on it crosses it.
  int32_t exact = 0;
  const bool owned = f.primitive == any.owners[0] || f.primitive == any.owners[1];
  const double at_eye = glm::dot(m, replay.eye_position - replay.centre);
  if (!owned && (at_eye > 0.0) != (at_point > 0.0) && at_point != 0.0) {
    const dvec3 x_world =
        replay.eye_position + (at_eye / (at_eye - at_point)) * (f.p - replay.eye_position);
    const dvec3 v = x_world - replay.centre;
    const double alpha = glm::dot(glm::cross(v, e.b - replay.centre), m) / mm;
    const double beta = glm::dot(glm::cross(e.a - replay.centre, v), m) / mm;
    if (alpha >= 0.0 && beta >= 0.0 && alpha + beta >= 1.0 &&
        glm::dot(replay.forward, x_world - replay.eye_position) > replay.near_plane)
      exact = any.payload * any.facing;
  }
  return exact - stencil;
}

int32_t capCrossings(const Scene& scene, const std::vector<uint32_t>& neighbours,
                     const PixelBasis& f, const dvec3& centre, const dvec3& eye_position) {
  int32_t shift = 0;
  for (const uint32_t id : neighbours) {
    const auto [m, t] = scene.locateTriangle(id);
    const Mesh& mesh = scene.meshes[m];
    const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
    if (!segmentHitsTriangle(eye_position, f.p - eye_position, 1.0, a, b, c)) continue;
    const dvec3 n = glm::cross(b - a, c - a);
    const double at_eye = glm::dot(n, eye_position - a);
    const double at_centre = glm::dot(n, centre - a);
    if (at_centre == 0.0) continue;  // edge-on to the centre: no volume
    shift += (at_eye > 0.0) == (at_centre > 0.0) ? 1 : -1;
  }
  return shift;
}

int32_t centreCountShift(const PotentialEdge& e, const EdgeTriangle* triangles,
                         const PixelBasis& f, const dvec3& centre, const dvec3& eye) {
  // The quad is the part of the plane through the centre and the edge beyond the edge: the
  // points x = centre + alpha (a - centre) + beta (b - centre), alpha, beta >= 0,
  // alpha + beta >= 1. From such a point the segment toward the centre passes through the edge.
  const dvec3& from = f.start.depth_point;
  // An edge of the visible triangle: the origin was snapped onto the triangle, often right at
  // this edge, and the depth-buffer point may lie just past it; the stencil never drew the
  // edge's quad here, so the neighbours' crossings are compared directly, where the
  // depth-buffer point is clear of a neighbour's plane.
  bool own = false;
  for (uint32_t k = 0; k < e.triangle_count; ++k)
    own = own || triangles[e.first_triangle + k].id == f.primitive;
  if (own) {
    int32_t shift = 0;
    const double scale = glm::length(from - eye);
    for (uint32_t k = 0; k < e.triangle_count; ++k) {
      const EdgeTriangle& t = triangles[e.first_triangle + k];
      if (t.id == f.primitive) continue;
      const int32_t at_origin =
          int32_t(segmentHitsTriangle(f.p, centre - f.p, 1.0 - kTfarShrink, e.a, e.b, t.opposite));
      // A depth-buffer point on the neighbour's plane (a smooth surface, a flat one split in
      // two) is a point of the neighbour's surface: the stencil counted the neighbour as it
      // counts the visible triangle, when the point lies on it and the centre is behind it.
      const double at_depth_point = glm::dot(t.normal, from) + t.offset;
      const int32_t stencil_counted =
          std::fabs(at_depth_point) <= 1e-6 * scale
              ? int32_t((glm::dot(t.normal, centre) + t.offset > 0.0) !=
                            (glm::dot(t.normal, eye) + t.offset > 0.0) &&
                        pointOnTriangle(from, e.a, e.b, t.opposite))
              : int32_t(segmentHitsTriangle(from, centre - from, 1.0 - kTfarShrink, e.a, e.b,
                                            t.opposite));
      shift += at_origin - stencil_counted;
    }
    return shift;
  }
  const dvec3 ca = e.a - centre, cb = e.b - centre;
  const dvec3& m = e.centre_normal;
  const double at_from = glm::dot(m, from - centre), at_to = glm::dot(m, f.p - centre);
  if ((at_from > 0.0) == (at_to > 0.0)) return 0;
  // The stencil found the depth-buffer point's side of the quad by comparing depths along the
  // eye's ray in float: where the quad meets that ray within 1e-5 of the point's distance (a
  // quad in the plane of the visible surface, the light centre in that plane), the side it
  // took is rounding, and no shift is known.
  if (std::fabs(at_from) <= 1e-5 * std::fabs(glm::dot(m, from - eye))) return 0;
  const double mm = glm::dot(m, m);
  if (!(mm > 0.0)) return 0;
  const dvec3 x = from + (at_from / (at_from - at_to)) * (f.p - from) - centre;
  const double alpha = glm::dot(glm::cross(x, cb), m) / mm;
  const double beta = glm::dot(glm::cross(ca, x), m) / mm;
  if (!(alpha >= 0.0 && beta >= 0.0 && alpha + beta >= 1.0)) return 0;
  // Just off the quad on one side, the segment toward the centre passes beside the edge on
  // that side and crosses the triangles of the edge that lie there: on the shaded point's side
  // it starts crossing them (+1 each), on the depth-buffer point's it stops (-1 each).
  // A triangle within rounding of that plane is edge-on to the centre: the stencil's volumes
  // leave it out (silhouette.h), and so does the shift.
  const bool to_side = at_to > 0.0;
  const double m_length = std::sqrt(mm);
  int32_t shift = 0;
  for (uint32_t k = 0; k < e.triangle_count; ++k) {
    const EdgeTriangle& t = triangles[e.first_triangle + k];
    const dvec3 to_opposite = t.opposite - centre;
    const double side = glm::dot(m, to_opposite);
    if (std::fabs(side) <= 1e-9 * m_length * glm::length(to_opposite)) continue;
    shift += (side > 0.0) == to_side ? 1 : -1;
  }
  return shift;
}

namespace {

// The fields of a pixel's basis the exact test reads, as PixelLanes holds them.
struct PointBasis {
  dvec3 p, axis, tangent, bitangent;
  double z_min, light_radius, light_near;
  uint32_t primitive;
};

// The exact test after the silhouette weight (edgeAtPixel): the edge's points a and b relative
// to p, their depths along the axis; false when it changes no sample, else `out` and the
// pseudo-angle range [from, to] of its sector (sampleRuns' arguments). The SIMD twin
// (pixel_edges_simd.cpp) repeats these operations in this order.
bool edgeSector(int32_t weight, dvec3 a, dvec3 b, double za, double zb, const PointBasis& f,
                SampleEdge& out, double& from, double& to) {
  // Clip to z >= z_min: the part behind projects outside the light.
  if (za < f.z_min) {
    a += (b - a) * ((f.z_min - za) / (zb - za));
    za = f.z_min;
  } else if (zb < f.z_min) {
    b += (a - b) * ((f.z_min - zb) / (za - zb));
    zb = f.z_min;
  }
  const dvec2 a2(glm::dot(a, f.tangent) / za, glm::dot(a, f.bitangent) / za);
  const dvec2 b2(glm::dot(b, f.tangent) / zb, glm::dot(b, f.bitangent) / zb);
  // Distance from the centre (0, 0) to the projected segment: beyond the light, no sample.
  const dvec2 ab = b2 - a2;
  const double ab2 = glm::dot(ab, ab);
  const double t = ab2 > 0.0 ? std::clamp(-glm::dot(a2, ab) / ab2, 0.0, 1.0) : 0.0;
  if (glm::length(a2 + t * ab) > f.light_radius) return false;
  // Sector lines through the centre and each projected end: n_a = axis x a gives the value
  // -a.B x + a.T y, up to the positive factor 1 / z_a. Normalised in double, then rounded,
  // the same way for every edge sharing the end, so the half-open rule is watertight.
  auto sectorLine = [&f](const dvec3& v, float line[2]) {
    const double s = -glm::dot(v, f.bitangent), u = glm::dot(v, f.tangent);
    const double scale = std::max(std::fabs(s), std::fabs(u));
    line[0] = float(s / scale);
    line[1] = float(u / scale);
    return dvec2(s / scale, u / scale);
  };
  const dvec2 la = sectorLine(a, out.sector_a);
  const dvec2 lb = sectorLine(b, out.sector_b);
  const double a_at_b = la.x * b2.x + la.y * b2.y;
  const double b_at_a = lb.x * a2.x + lb.y * a2.y;
  if (a_at_b == 0.0 || b_at_a == 0.0) return false;  // the centre on the edge's line: a tie
  out.a_side = a_at_b > 0.0;
  out.b_side = b_at_a > 0.0;
  // The edge's line: the plane through p and the edge, n . (T x + B y + axis).
  const dvec3 n = glm::cross(a, b);
  const dvec3 l(glm::dot(n, f.tangent), glm::dot(n, f.bitangent), glm::dot(n, f.axis));
  const double l_scale = std::max({std::fabs(l.x), std::fabs(l.y), std::fabs(l.z)});
  out.line[0] = float(l.x / l_scale);
  out.line[1] = float(l.y / l_scale);
  out.line[2] = float(l.z / l_scale);
  out.centre_side = out.line[2] >= 0.0f;
  // Crossing from the centre's side onto the other: the triangles on that side (+1 each) are
  // entered, those on the centre's side (-1 each) left.
  out.delta = out.centre_side ? -weight : weight;
  // The sector's angles: the shorter way round from one projected end to the other.
  const double angle_a = pseudoAngle(a2.x, a2.y), angle_b = pseudoAngle(b2.x, b2.y);
  double turn = angle_b - angle_a;
  if (turn > 2.0) turn -= 4.0;
  if (turn <= -2.0) turn += 4.0;
  from = turn >= 0.0 ? angle_a : angle_b;
  to = turn >= 0.0 ? angle_a + turn : angle_b - turn;
  return true;
}

// The silhouette from p: the signed number of the edge's triangles on each side of the plane
// through p and the edge, from each triangle's own plane (EdgeTriangle). Left out: the visible
// triangle; triangles whose plane misses the light and has p and the light centre on one side
// (no segment from p to the light crosses them; the stencil does not count them at the centre
// either); and triangles whose plane cuts the light unless they lie wholly in front of it (the
// others are counted sample by sample). `inFront(t)` says which of the last: kCounts, kSkipped,
// or kUndecided, which stops the count (false).
enum class CutPlace { kCounts, kSkipped, kUndecided };
template <class InFront>
bool silhouetteWeight(const PotentialEdge& e, const EdgeTriangle* triangles, const dvec3& p,
                      uint32_t primitive, InFront&& inFront, int32_t& weight) {
  weight = 0;
  for (uint32_t k = 0; k < e.triangle_count; ++k) {
    const EdgeTriangle& t = triangles[e.first_triangle + k];
    if (t.id == primitive) continue;
    const double at_p = glm::dot(t.normal, p) + t.offset;
    if (t.cuts) {
      const CutPlace place = inFront(t);
      if (place == CutPlace::kUndecided) return false;
      if (place == CutPlace::kSkipped) continue;
    } else if ((at_p > 0.0) == t.light_above) {
      continue;
    }
    weight -= t.winding * ((at_p > 0.0) - (at_p < 0.0));
  }
  return true;
}

PointBasis pointBasis(const PixelLanes& lanes, int k) {
  return PointBasis{dvec3(lanes.px[k], lanes.py[k], lanes.pz[k]),
                    dvec3(lanes.ax[k], lanes.ay[k], lanes.az[k]),
                    dvec3(lanes.tx[k], lanes.ty[k], lanes.tz[k]),
                    dvec3(lanes.bx[k], lanes.by[k], lanes.bz[k]),
                    lanes.z_min[k],
                    lanes.light_radius[k],
                    lanes.light_near[k],
                    uint32_t(lanes.primitive[k])};
}

}  // namespace

void PixelLanes::setLane(int k, const PixelBasis& f) {
  px[k] = f.p.x, py[k] = f.p.y, pz[k] = f.p.z;
  ax[k] = f.axis.x, ay[k] = f.axis.y, az[k] = f.axis.z;
  tx[k] = f.tangent.x, ty[k] = f.tangent.y, tz[k] = f.tangent.z;
  bx[k] = f.bitangent.x, by[k] = f.bitangent.y, bz[k] = f.bitangent.z;
  z_min[k] = f.z_min;
  light_radius[k] = f.light_radius;
  light_near[k] = f.light_near;
  primitive[k] = double(f.primitive);
}

uint32_t edgeAtPixelsScalar(const PotentialEdge& e, const EdgeTriangle* triangles,
                            const PixelLanes& pixels, const SortedSamples& samples,
                            EdgeLanes& out) {
  uint32_t accepted = 0;
  out.deferred = 0;
  for (int k = 0; k < pixels.count; ++k) {
    const PointBasis f = pointBasis(pixels, k);
    const dvec3 a = e.a - f.p, b = e.b - f.p;
    const double za = glm::dot(a, f.axis), zb = glm::dot(b, f.axis);
    if (za <= f.z_min && zb <= f.z_min) continue;
    // classifyCutting's quick test alone (the whole triangle nearer than the light: InFront);
    // where it fails, only the clipped test decides: edgeAtPixel's.
    const double limit = f.light_near * (1.0 - 1e-9);
    auto quickInFront = [&](const EdgeTriangle& t) {
      return std::max({za, zb, glm::dot(t.opposite - f.p, f.axis)}) < limit
                 ? CutPlace::kCounts
                 : CutPlace::kUndecided;
    };
    int32_t weight = 0;
    if (!silhouetteWeight(e, triangles, f.p, f.primitive, quickInFront, weight)) {
      out.deferred |= 1u << k;
      continue;
    }
    if (weight == 0) continue;
    out.weight[k] = weight;
    if (!edgeSector(weight, a, b, za, zb, f, out.edge[k], out.from[k], out.to[k])) continue;
    out.runs[k] = sampleRuns(samples, out.from[k], out.to[k]);
    accepted |= 1u << k;
  }
  return accepted;
}

// The exact test of one edge at one point: false when the edge changes none of its samples,
// else `out` says which samples it changes and by how much.
bool edgeAtPixel(const PotentialEdge& e, const EdgeTriangle* triangles, const PixelBasis& f,
                 const SortedSamples& samples, PixelEdge& pixel_edge, int32_t& weight_out) {
  const dvec3& p = f.p;
  const dvec3 a = e.a - p, b = e.b - p;
  const double za = glm::dot(a, f.axis), zb = glm::dot(b, f.axis);
  if (za <= f.z_min && zb <= f.z_min) return false;  // behind the point: no ray toward the light
  int32_t weight = 0;
  silhouetteWeight(e, triangles, p, f.primitive,
                   [&](const EdgeTriangle& t) {
                     return classifyCutting(e.a, e.b, t.opposite, f) == CuttingPlace::InFront
                                ? CutPlace::kCounts
                                : CutPlace::kSkipped;
                   },
                   weight);
  if (weight == 0) return false;
  const PointBasis basis{p,      f.axis,         f.tangent,     f.bitangent,
                         f.z_min, f.light_radius, f.light_near, f.primitive};
  double from = 0.0, to = 0.0;
  if (!edgeSector(weight, a, b, za, zb, basis, pixel_edge.edge, from, to)) return false;
  weight_out = weight;
  pixel_edge.runs = sampleRuns(samples, from, to);
  return true;
}

}  // namespace penumbra
