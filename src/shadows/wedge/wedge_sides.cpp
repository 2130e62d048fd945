#include "shadows/wedge/wedge_sides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace penumbra::wedge_detail {
namespace {

// Figure 6 cut: the bottom plane is placed this far from the edge toward the first crossing
// (as a fraction of the axial distance), late enough to keep most of the wedge, early enough
// that the bottom face does not collapse to the crossing point.
constexpr double kCutFraction = 0.9;
// Rays must advance along the bottom plane's axis at least this fast (cosine) to be cut.
constexpr double kMinAxisCos = 1e-3;

dvec3 unitOr(const dvec3& v, const dvec3& fallback) {
  const double len = glm::length(v);
  if (len > 1e-300 && std::isfinite(len)) return v / len;
  return fallback;
}

// Some unit vector perpendicular to the unit vector d.
dvec3 anyPerpendicular(const dvec3& d) {
  const dvec3 ad = glm::abs(d);
  const dvec3 axis = ad.x <= ad.y && ad.x <= ad.z ? dvec3(1, 0, 0)
                     : ad.y <= ad.z               ? dvec3(0, 1, 0)
                                                  : dvec3(0, 0, 1);
  return unitOr(glm::cross(d, axis), dvec3(1, 0, 0));
}

// Unit direction of the line where planes with unit normals n0 and n1 meet, pointing away from
// the light (positive along `away` = vertex - c). Parallel or identical planes (collinear
// edges): `away` projected into the plane n0 (section 4.1 gives no rule; this keeps the line in
// the plane and as close to the light direction as possible).
dvec3 lineDirection(const dvec3& n0, const dvec3& n1, const dvec3& away) {
  const dvec3 away_unit = unitOr(away, anyPerpendicular(n0));
  dvec3 d = glm::cross(n0, n1);
  const double len = glm::length(d);
  if (len > kParallelSin) {
    d /= len;
  } else {
    d = unitOr(away_unit - glm::dot(away_unit, n0) * n0, anyPerpendicular(n0));
  }
  return glm::dot(d, away) < 0.0 ? -d : d;
}

// Orients the side-plane normal inward for the wedge ending at it: the chain crosses the plane
// from + (the ending edge, direction t_in) to - (the starting edge, t_out). For unit t's the
// corner's bisector plane has normal +-(t_in + t_out), so that sum decides the sign robustly.
dvec3 orientSide(const dvec3& sn, const dvec3& t_in, const dvec3& t_out) {
  const dvec3 sum = t_in + t_out;
  const dvec3 probe = glm::length(sum) > 1e-9 ? sum : t_in;
  return glm::dot(sn, probe) > 0.0 ? -sn : sn;
}

Plane planeThrough(const dvec3& n, const dvec3& p) { return Plane{n, -glm::dot(n, p)}; }

// The equation (2) direction: `m` (the sum of the two quad normals) projected into the side
// plane (section 4.1, last paragraph before Figure 7). If m is perpendicular to the plane (a
// hairpin), the plane's direction across `line` toward `toward`.
dvec3 sideDirection(const dvec3& m, const dvec3& sn, const dvec3& line, const dvec3& toward) {
  const dvec3 projected = m - glm::dot(m, sn) * sn;
  if (glm::length(projected) > 1e-9 * std::max(1.0, glm::length(m))) return unitOr(projected, line);
  const dvec3 across = unitOr(glm::cross(sn, line), anyPerpendicular(sn));
  return glm::dot(across, toward) < 0.0 ? -across : across;
}

}  // namespace

EdgePlanes edgePlanes(const UnitEdge& e, const dvec3& c, double r) {
  const dvec3 mid = 0.5 * (e.a + e.b);
  EdgePlanes p;
  // r == 0: the hard quad's plane. The back plane is the front negated exactly, so a wedge of a
  // point light has no interior and its umbra quad is the hard quad.
  p.front = Plane{-e.n, glm::dot(e.n, mid)};
  p.back = Plane{-p.front.n, -p.front.d};
  if (!(r > 0.0)) return p;
  const dvec3 ab = e.b - e.a;
  const dvec3 f = c - r * e.n;
  const dvec3 bp = c + r * e.n;
  // Either plane is the quad's plane turned about the edge line by atan(r / distance) < 90
  // degrees, so its normal's sign relative to n is never ambiguous: the front plane's inward
  // side (toward the shadow) is against n, the back plane's (toward the light) along n.
  dvec3 fn = unitOr(glm::cross(ab, f - mid), -e.n);
  if (glm::dot(fn, e.n) > 0.0) fn = -fn;
  dvec3 bn = unitOr(glm::cross(ab, bp - mid), e.n);
  if (glm::dot(bn, e.n) < 0.0) bn = -bn;
  p.front = planeThrough(fn, mid);
  p.back = planeThrough(bn, mid);
  return p;
}

SidePlane regularSide(const UnitEdge& in, const EdgePlanes& pin, const UnitEdge& out,
                      const EdgePlanes& pout, const dvec3& c, double r, const dvec3& hard) {
  const dvec3 v = in.b;
  const dvec3 away = v - c;
  SidePlane s;
  dvec3 d_f = hard, d_b = hard;
  if (r > 0.0) {
    d_f = lineDirection(pin.front.n, pout.front.n, away);
    d_b = lineDirection(pin.back.n, pout.back.n, away);
  }
  // The plane holding both lines (Figure 5). They coincide with r == 0 (or nearly, for a tiny
  // light): then the plane holding the front line and the average quad normal, which is the
  // limit of the general plane as r -> 0.
  dvec3 sn = glm::cross(d_f, d_b);
  const double len = glm::length(sn);
  if (len > kParallelSin) {
    sn /= len;
  } else {
    sn =
        unitOr(glm::cross(d_f, in.n + out.n), unitOr(glm::cross(d_f, in.t), anyPerpendicular(d_f)));
  }
  sn = orientSide(sn, in.t, out.t);
  s.plane = planeThrough(sn, v);
  s.front_in = s.front_out = d_f;
  s.back_in = s.back_out = d_b;
  s.dir = sideDirection(in.n + out.n, sn, d_f, in.n);
  return s;
}

SidePlane bridgedSide(const UnitEdge& in, const EdgePlanes& pin, const UnitEdge& out,
                      const EdgePlanes& pout, const dvec3& c, double r, const dvec3& hard_v,
                      const dvec3& hard_w) {
  const dvec3 v = in.b, w = out.a;
  const dvec3 m = in.n + out.n;
  const dvec3 vw = w - v;
  const dvec3 q = glm::cross(vw, m);
  if (!(glm::length(q) > kParallelSin * glm::length(vw) * glm::length(m))) {
    // v == w (the run came back to its start) or a hairpin: join as if the edges met at v.
    return regularSide(in, pin, out, pout, c, r, hard_v);
  }
  // The plane through v and w holding m: seen from the light it is the bisector of the corner
  // the two edges make (m is perpendicular to t_in + t_out in that view), and it contains both
  // wedges' end vertices, so both polyhedra stay closed at their a and b.
  const dvec3 sn = orientSide(q / glm::length(q), in.t, out.t);
  SidePlane s;
  s.plane = planeThrough(sn, v);
  if (r > 0.0) {
    s.front_in = lineDirection(pin.front.n, sn, v - c);
    s.back_in = lineDirection(pin.back.n, sn, v - c);
    s.front_out = lineDirection(pout.front.n, sn, w - c);
    s.back_out = lineDirection(pout.back.n, sn, w - c);
  } else {
    s.front_in = s.back_in = hard_v;
    s.front_out = s.back_out = hard_w;
  }
  s.dir = sideDirection(m, sn, s.front_in, in.n);
  return s;
}

SidePlane loneSide(const UnitEdge& e, bool at_b, const dvec3& c, double r, const dvec3& hard) {
  const dvec3 v = at_b ? e.b : e.a;
  dvec3 sn = unitOr(glm::cross(v - c, e.n), e.t);
  // Inward for e: toward its other end.
  if (at_b ? glm::dot(sn, e.t) > 0.0 : glm::dot(sn, e.t) < 0.0) sn = -sn;
  SidePlane s;
  s.plane = planeThrough(sn, v);
  // The plane holds f and c + r n, so it meets the front plane along the line from f through v
  // and the back plane along the line from c + r n through v.
  s.front_in = r > 0.0 ? unitOr(v - (c - r * e.n), hard) : hard;
  s.back_in = r > 0.0 ? unitOr(v - (c + r * e.n), hard) : hard;
  s.front_out = s.front_in;
  s.back_out = s.back_in;
  s.dir = e.n;
  return s;
}

bool sideFits(const UnitEdge& e, const EdgePlanes& planes, const Plane& inward,
              const dvec3& ray_front, const dvec3& ray_back, bool at_b, const dvec3& c, double r) {
  if (!(r > 0.0)) return true;
  // Relative to the sine of the front/back dihedral angle, which is what a ray leaving the edge
  // squarely would give (~2 r / distance): a ray must be at least kFit of the way there.
  constexpr double kFit = 1e-3;
  const double dihedral = glm::length(glm::cross(planes.front.n, planes.back.n));
  const double len = glm::length(e.b - e.a);
  if (!(glm::dot(planes.back.n, ray_front) > kFit * dihedral &&
        glm::dot(planes.front.n, ray_back) > kFit * dihedral &&
        inward.eval(at_b ? e.a : e.b) > kFit * dihedral * len))
    return false;
  // A ray from a point of the light through v deviates from v - c by at most the light's
  // angular radius asin(r / |v - c|). The paper's shared lines leave that cone at acute
  // corners (two front planes meet 1 / sin(corner / 2) times farther out than one), and the
  // umbra quads following them become spikes that the wedges, cut where their side planes
  // cross (Figure 6), no longer cover: long dark streaks. kCone times the cone is allowed: a
  // right-angle corner needs sqrt(2), a 60 degree one 2. Against the ray-traced oracle, 2 more
  // than halves the fractal scene's mean error, lowers year2002's and changes nothing in
  // spheres, columns and multilight; 1.2 splits right angles too and is worse on fractal and
  // columns (docs/wedge-accuracy.md has the errors).
  constexpr double kCone = 2.0;
  const dvec3 away = (at_b ? e.b : e.a) - c;
  const double dist = glm::length(away);
  if (!(dist > r)) return true;
  const double cone = std::asin(r / dist);
  const double min_cos = std::cos(std::min(kCone * cone, std::numbers::pi));
  return glm::dot(ray_front, away) >= min_cos * dist && glm::dot(ray_back, away) >= min_cos * dist;
}

bool cutWhereSidesCross(Wedge& w, const dvec3& c) {
  struct Ray {
    dvec3 o, u;
    const Plane* opposite;  // the side plane the ray does not lie in
    const Plane* across;    // the front or back plane it does not lie in
    dvec3* far;
  };
  const std::array<Ray, 4> rays = {{{w.a, w.ray_front_left, &w.right, &w.back, &w.far_front_left},
                                    {w.b, w.ray_front_right, &w.left, &w.back, &w.far_front_right},
                                    {w.a, w.ray_back_left, &w.right, &w.front, &w.far_back_left},
                                    {w.b, w.ray_back_right, &w.left, &w.front, &w.far_back_right}}};
  const double scale = glm::length(w.b - w.a);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Where each ray leaves through the opposite side plane. A front (back) ray can leave the
  // wedge only there: it starts on the edge, on the boundary of the back (front) plane's
  // inward side, and enters that side (sideFits made sure; checked again here), and the other
  // two planes contain it. The front rays cross each other exactly where they cross the
  // opposite side planes, so this is the paper's "side planes intersect" (Figure 6).
  std::array<double, 4> exit{};
  bool crosses = false;
  for (size_t i = 0; i < 4; ++i) {
    if (!(glm::dot(rays[i].across->n, rays[i].u) > 0.0)) return false;
    const double start = rays[i].opposite->eval(rays[i].o);
    // The edge's far end must be strictly inside the opposite side plane; else the side planes
    // cross at the edge itself and there is no wedge to cut.
    if (!(start > 1e-9 * scale)) return false;
    const double rate = glm::dot(rays[i].opposite->n, rays[i].u);
    exit[i] = rate < -1e-12 ? start / -rate : kInf;
    crosses = crosses || exit[i] < kInf;
  }
  if (!crosses) return true;
  // Axis of the bottom plane. Every ray must advance along it, and the cut must fall beyond
  // both edge ends and before every crossing. First choice: the bisector of the front/back
  // dihedral angle, perpendicular to the edge. Then a and b are level along it and every ray
  // (in the front or back plane, leaving the edge on the wedge's side) advances along it while
  // the dihedral angle is below 180 degrees, so the interval is never empty, even for short
  // edges steep to the light whose side planes cross close to the edge. Fallbacks: the mean
  // ray direction, the direction from the light to the edge.
  const dvec3 edge_t = unitOr(w.b - w.a, dvec3(0.0));
  dvec3 along_front = unitOr(glm::cross(w.front.n, edge_t), dvec3(0.0));
  if (glm::dot(along_front, w.back.n) < 0.0) along_front = -along_front;
  dvec3 along_back = unitOr(glm::cross(w.back.n, edge_t), dvec3(0.0));
  if (glm::dot(along_back, w.front.n) < 0.0) along_back = -along_back;
  const std::array<dvec3, 3> axes = {
      unitOr(along_front + along_back, dvec3(0.0)),
      unitOr(w.ray_front_left + w.ray_front_right + w.ray_back_left + w.ray_back_right, dvec3(0.0)),
      unitOr(0.5 * (w.a + w.b) - c, dvec3(0.0))};
  for (const dvec3& axis : axes) {
    if (glm::length(axis) == 0.0) continue;
    std::array<double, 4> rate{};
    bool advancing = true;
    for (size_t i = 0; i < 4; ++i) {
      rate[i] = glm::dot(axis, rays[i].u);
      advancing = advancing && rate[i] > kMinAxisCos;
    }
    if (!advancing) continue;
    const double lo = std::max(glm::dot(axis, w.a), glm::dot(axis, w.b));
    double hi = kInf;
    for (size_t i = 0; i < 4; ++i)
      if (exit[i] < kInf) hi = std::min(hi, glm::dot(axis, rays[i].o) + exit[i] * rate[i]);
    if (!(hi > lo + 1e-9 * scale)) continue;
    const double h = lo + kCutFraction * (hi - lo);
    std::array<dvec3, 4> far{};
    bool convex = true;
    for (size_t i = 0; i < 4; ++i) {
      const double t = (h - glm::dot(axis, rays[i].o)) / rate[i];
      far[i] = rays[i].o + t * rays[i].u;
      // Before its crossing a far point is inside the four planes; check against rounding.
      const double tol = 1e-9 * (scale + t);
      convex = convex && w.front.eval(far[i]) > -tol && w.back.eval(far[i]) > -tol &&
               w.left.eval(far[i]) > -tol && w.right.eval(far[i]) > -tol;
    }
    if (!convex) continue;
    for (size_t i = 0; i < 4; ++i) *rays[i].far = far[i];
    w.bottom = Plane{-axis, h};
    w.finite = true;
    return true;
  }
  return false;
}

}  // namespace penumbra::wedge_detail
