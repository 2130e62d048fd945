#include "shadows/coverage/shape_coverage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shadows/coverage/disk_coverage_kernel.h"

namespace penumbra {
namespace {

// Area of the square [-1, 1]^2 inside the cone from the origin between directions lo and hi
// (counter-clockwise from lo to hi, less than pi apart): the square clipped by the two
// half-planes through the origin (Sutherland-Hodgman), then the shoelace formula.
double squareConeArea(const dvec2& lo, const dvec2& hi) {
  dvec2 poly[8] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  int count = 4;
  const auto clip = [&](const dvec2& dir, double sign) {
    dvec2 out[8];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const dvec2 p = poly[i], q = poly[(i + 1) % count];
      const double fp = sign * cross2(dir, p), fq = sign * cross2(dir, q);
      if (fp >= 0.0) out[n++] = p;
      if ((fp >= 0.0) != (fq >= 0.0)) out[n++] = p + (q - p) * (fp / (fp - fq));
    }
    count = n;
    std::copy(out, out + n, poly);
  };
  clip(lo, 1.0);   // left of lo
  clip(hi, -1.0);  // right of hi
  double area = 0.0;
  for (int i = 0; i < count; ++i) area += cross2(poly[i], poly[(i + 1) % count]);
  return 0.5 * area;
}

// Convex polygons of at most kMaxVertices vertices, clipped by half-planes in turn.
constexpr int kMaxVertices = 12;
struct Polygon {
  dvec2 v[kMaxVertices];
  int count = 0;
  // Keeps the side where n . x + offset >= 0 (Sutherland-Hodgman).
  void clip(const dvec2& n, double offset) {
    dvec2 out[kMaxVertices];
    int k = 0;
    for (int i = 0; i < count && k + 2 <= kMaxVertices; ++i) {
      const dvec2 p = v[i], q = v[(i + 1) % count];
      const double fp = glm::dot(n, p) + offset, fq = glm::dot(n, q) + offset;
      if (fp >= 0.0) out[k++] = p;
      if ((fp >= 0.0) != (fq >= 0.0)) out[k++] = p + (q - p) * (fp / (fp - fq));
    }
    count = k;
    std::copy(out, out + k, v);
  }
  double area() const {
    double a = 0.0;
    for (int i = 0; i < count; ++i) a += cross2(v[i], v[(i + 1) % count]);
    return 0.5 * a;
  }
};

// Signed area of the triangle (origin, p, q) inside the unit disk: the segment from p to q split
// where it crosses the circle; a piece inside adds its triangle with the origin, a piece outside
// the circular sector its directions span.
double originTriangleInUnitDisk(const dvec2& p, const dvec2& q) {
  const dvec2 d = q - p;
  const double a = glm::dot(d, d), b = glm::dot(p, d), c = glm::dot(p, p) - 1.0;
  double t[4] = {0.0, 0.0, 0.0, 1.0};
  int n = 1;
  const double disc = b * b - a * c;
  if (a > 0.0 && disc > 0.0) {
    const double root = std::sqrt(disc);
    for (const double ti : {(-b - root) / a, (-b + root) / a})
      if (ti > 0.0 && ti < 1.0) t[n++] = ti;
  }
  t[n++] = 1.0;
  double area = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const dvec2 u = p + t[i] * d, w = p + t[i + 1] * d;
    const dvec2 mid = 0.5 * (u + w);
    if (glm::dot(mid, mid) <= 1.0) {
      area += 0.5 * cross2(u, w);
    } else {
      area += 0.5 * std::atan2(cross2(u, w), glm::dot(u, w));
    }
  }
  return area;
}

}  // namespace

double insideFractionInHalfPlane(LightOutline outline, const dvec2& lo, const dvec2& hi,
                                 const dvec2& n, double offset) {
  const double turn = cross2(lo, hi);
  if (turn == 0.0) return 0.0;
  const dvec2 a = turn > 0.0 ? lo : hi, b = turn > 0.0 ? hi : lo;
  // The cone from the centre between a and b (less than pi wide: the segment misses the
  // centre), within a square holding the light, on the kept side.
  const double reach = outline == LightOutline::Disk ? 2.0 : 1.0;
  Polygon cone;
  cone.count = 4;
  cone.v[0] = {-reach, -reach};
  cone.v[1] = {reach, -reach};
  cone.v[2] = {reach, reach};
  cone.v[3] = {-reach, reach};
  cone.clip(dvec2(-a.y, a.x), 0.0);  // left of a
  cone.clip(dvec2(b.y, -b.x), 0.0);  // right of b
  cone.clip(n, offset);
  double cone_area = 0.0;
  if (outline == LightOutline::Disk) {
    for (int i = 0; i < cone.count; ++i)
      cone_area += originTriangleInUnitDisk(cone.v[i], cone.v[(i + 1) % cone.count]);
  } else {
    cone_area = cone.area();
  }
  Polygon triangle;
  triangle.count = 3;
  triangle.v[0] = {0.0, 0.0};
  triangle.v[1] = a;
  triangle.v[2] = b;
  triangle.clip(n, offset);
  const double area =
      (cone_area - triangle.area()) / (outline == LightOutline::Disk ? std::numbers::pi : 4.0);
  return turn > 0.0 ? area : -area;
}

double insideFraction(LightOutline outline, const dvec2& lo, const dvec2& hi) {
  const double turn = cross2(lo, hi);
  if (turn == 0.0) return 0.0;  // through the centre, or a point: the quad's plane itself
  const dvec2 a = turn > 0.0 ? lo : hi, b = turn > 0.0 ? hi : lo;
  const double triangle = 0.5 * std::fabs(turn);
  double area;
  if (outline == LightOutline::Disk) {
    area = 0.5 * std::atan2(cross2(a, b), glm::dot(a, b)) - triangle;
    area /= std::numbers::pi;
  } else {
    area = (squareConeArea(a, b) - triangle) / 4.0;
  }
  return turn > 0.0 ? area : -area;
}

bool clipToOutline(LightOutline outline, const dvec3& a_in, const dvec3& b_in, dvec2& lo,
                   dvec2& hi) {
  const double min_depth = kMinDepth;
  const bool keep0 = a_in.z >= min_depth, keep1 = b_in.z >= min_depth;
  if (!keep0 && !keep1) return false;
  dvec3 a = a_in, b = b_in;
  if (!keep0 || !keep1) {
    const double t = (min_depth - a_in.z) / (b_in.z - a_in.z);
    const dvec3 cut = a_in + t * (b_in - a_in);
    (keep0 ? b : a) = dvec3(cut.x, cut.y, min_depth);
  }
  // The line l = A x B: distance from the centre and unit direction from A to B.
  const dvec3 l = glm::cross(a, b);
  const double n = std::hypot(l.x, l.y);
  if (!(n > 0.0)) return false;
  const dvec2 u(l.y / n, -l.x / n);
  const dvec2 m = -l.z / (n * n) * dvec2(l.x, l.y);  // closest point to the centre
  double s_lo = glm::dot(dvec2(a), u) / a.z, s_hi = glm::dot(dvec2(b), u) / b.z;
  if (outline == LightOutline::Disk) {
    const double h2 = 1.0 - glm::dot(m, m);
    if (!(h2 > 0.0)) return false;
    const double h = std::sqrt(h2);
    s_lo = std::max(s_lo, -h);
    s_hi = std::min(s_hi, h);
  } else {
    // Slabs |m + s u| <= 1 per axis.
    for (int k = 0; k < 2; ++k) {
      if (u[k] == 0.0) {
        if (std::fabs(m[k]) > 1.0) return false;
        continue;
      }
      const double t0 = (-1.0 - m[k]) / u[k], t1 = (1.0 - m[k]) / u[k];
      s_lo = std::max(s_lo, std::min(t0, t1));
      s_hi = std::min(s_hi, std::max(t0, t1));
    }
  }
  if (!(s_hi > s_lo)) return false;
  lo = m + s_lo * u;
  hi = m + s_hi * u;
  return true;
}

double beyondFractionHomogeneous(LightOutline outline, const dvec3& a, const dvec3& b) {
  dvec2 lo, hi;
  if (!clipToOutline(outline, a, b, lo, hi)) return 0.0;
  return insideFraction(outline, lo, hi);
}

double halfPlaneFraction(LightOutline outline, const dvec2& n, double offset) {
  const double length = glm::length(n);
  if (!(length > 0.0)) return offset > 0.0 ? 1.0 : 0.0;
  if (outline == LightOutline::Disk) {
    // Signed distance of the centre from the line, positive on the kept side; the cut-off
    // circular segment at distance h has area acos(h) - h sqrt(1 - h^2).
    const double d = std::clamp(offset / length, -1.0, 1.0);
    const double h = std::fabs(d);
    const double segment = std::acos(h) - h * std::sqrt(std::max(0.0, 1.0 - h * h));
    return d >= 0.0 ? 1.0 - segment / std::numbers::pi : segment / std::numbers::pi;
  }
  dvec2 poly[8] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  dvec2 out[8];
  int count = 0;
  for (int i = 0; i < 4; ++i) {
    const dvec2 p = poly[i], q = poly[(i + 1) % 4];
    const double fp = glm::dot(n, p) + offset, fq = glm::dot(n, q) + offset;
    if (fp > 0.0) out[count++] = p;
    if ((fp > 0.0) != (fq > 0.0)) out[count++] = p + (q - p) * (fp / (fp - fq));
  }
  double area = 0.0;
  for (int i = 0; i < count; ++i) area += cross2(out[i], out[(i + 1) % count]);
  return 0.5 * area / 4.0;
}

double beyondFraction(LightOutline outline, const dvec2& a, const dvec2& b) {
  return beyondFractionHomogeneous(outline, dvec3(a, 1.0), dvec3(b, 1.0));
}

}  // namespace penumbra
