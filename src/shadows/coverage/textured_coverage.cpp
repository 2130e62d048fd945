#include "shadows/coverage/textured_coverage.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace penumbra {

void clipSmallPolygon(const SmallPolygon& in, const dvec2& normal, double d, SmallPolygon& out) {
  out.n = 0;
  for (size_t k = 0; k < in.n; ++k) {
    const dvec2& p = in.v[k];
    const dvec2& q = in.v[(k + 1) % in.n];
    const double fp = glm::dot(normal, p) + d, fq = glm::dot(normal, q) + d;
    // A convex polygon cut by a line gains at most one corner: the capacity holds.
    if (fp >= 0.0 && out.n < SmallPolygon::kCapacity) out.v[out.n++] = p;
    if ((fp >= 0.0) != (fq >= 0.0) && out.n < SmallPolygon::kCapacity) {
      out.v[out.n++] = p + (q - p) * (fp / (fp - fq));
    }
  }
  if (out.n < 3) out.n = 0;
}

std::vector<dvec2> clipPolygonToHalfPlane(const std::vector<dvec2>& polygon, const dvec2& n,
                                          double d) {
  PENUMBRA_CHECK(polygon.size() < SmallPolygon::kCapacity, "polygon of {} corners",
                 polygon.size());
  SmallPolygon in, out;
  for (const dvec2& p : polygon) in.v[in.n++] = p;
  clipSmallPolygon(in, n, d, out);
  return std::vector<dvec2>(out.v, out.v + out.n);
}

TexturedSquare::TexturedSquare(const LightTexture& texture)
    : width_(texture.width), height_(texture.height) {
  PENUMBRA_CHECK(width_ >= 1 && height_ >= 1 &&
                     texture.texels.size() == size_t(width_) * size_t(height_),
                 "light texture is malformed ({}x{}, {} texels)", width_, height_,
                 texture.texels.size());
  texels_.assign(texture.texels.begin(), texture.texels.end());
  prefix_.resize(size_t(width_ + 1) * size_t(height_));
  dvec3 total(0.0);
  for (int j = 0; j < height_; ++j) {
    dvec3 sum(0.0);
    for (int i = 0; i <= width_; ++i) {
      prefix_[size_t(j) * size_t(width_ + 1) + size_t(i)] = sum;
      if (i < width_) sum += texels_[size_t(j) * size_t(width_) + size_t(i)];
    }
    total += sum;
  }
  for (int c = 0; c < 3; ++c) inv_total_[c] = total[c] > 0.0 ? 1.0 / total[c] : 0.0;
}

dvec3 TexturedSquare::polygonFraction(const dvec2* polygon, size_t count) const {
  if (count < 3) return dvec3(0.0);
  const double su = 0.5 * width_, sv = 0.5 * height_;
  dvec3 integral(0.0);
  // 0, 1 and every texel border crossed (at most width - 1 + height - 1 of them).
  double breaks[2 * kMaxLightTextureCells + 2];
  for (size_t k = 0; k < count; ++k) {
    const dvec2 p((polygon[k].x + 1.0) * su, (polygon[k].y + 1.0) * sv);
    const dvec2& next = polygon[(k + 1) % count];
    const dvec2 q((next.x + 1.0) * su, (next.y + 1.0) * sv);
    const dvec2 d = q - p;
    if (d.y == 0.0) continue;  // F dV: a piece along a row adds nothing
    // Parameters where the edge crosses a texel border, in either direction.
    size_t n_breaks = 0;
    breaks[n_breaks++] = 0.0;
    breaks[n_breaks++] = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
      if (d[axis] == 0.0) continue;
      const double lo = std::min(p[axis], q[axis]), hi = std::max(p[axis], q[axis]);
      const int limit = axis == 0 ? width_ : height_;
      for (int border = std::max(1, int(std::floor(lo)) + 1);
           border < limit && double(border) < hi; ++border) {
        breaks[n_breaks++] = (double(border) - p[axis]) / d[axis];
      }
    }
    std::sort(breaks, breaks + n_breaks);
    for (size_t b = 0; b + 1 < n_breaks; ++b) {
      const double t0 = breaks[b], t1 = breaks[b + 1];
      if (!(t1 > t0)) continue;
      const dvec2 mid = p + d * (0.5 * (t0 + t1));
      const int i = std::clamp(int(std::floor(mid.x)), 0, width_ - 1);
      const int j = std::clamp(int(std::floor(mid.y)), 0, height_ - 1);
      const dvec3 f = prefix_[size_t(j) * size_t(width_ + 1) + size_t(i)] +
                      texels_[size_t(j) * size_t(width_) + size_t(i)] * (mid.x - double(i));
      integral += f * (d.y * (t1 - t0));
    }
  }
  // Green's theorem gives the integral for a counter-clockwise loop; rounding never makes a
  // share negative or above the whole.
  return glm::clamp(integral * inv_total_, dvec3(0.0), dvec3(1.0));
}

namespace {

SmallPolygon square() {
  SmallPolygon s;
  s.v[0] = {-1.0, -1.0};
  s.v[1] = {1.0, -1.0};
  s.v[2] = {1.0, 1.0};
  s.v[3] = {-1.0, 1.0};
  s.n = 4;
  return s;
}

}  // namespace

dvec3 TexturedSquare::beyondFraction(dvec2 lo, dvec2 hi, bool flip_y, bool half_plane,
                                     dvec2 slope, double offset) const {
  const double turn = cross2(lo, hi);
  if (turn == 0.0) return dvec3(0.0);  // a point, or a line through the centre
  if (flip_y) {
    lo.y = -lo.y;
    hi.y = -hi.y;
    slope.y = -slope.y;
  }
  // Counter-clockwise in the texture's own orientation.
  const bool ccw = cross2(lo, hi) > 0.0;
  const dvec2 a = ccw ? lo : hi, b = ccw ? hi : lo;
  SmallPolygon one, two;
  clipSmallPolygon(square(), dvec2(-a.y, a.x), 0.0, one);  // a x X >= 0
  clipSmallPolygon(one, dvec2(b.y, -b.x), 0.0, two);       // X x b >= 0
  // The chord's far side: (b - a) x (X - a) <= 0.
  const dvec2 e = b - a;
  clipSmallPolygon(two, dvec2(e.y, -e.x), -(e.y * a.x - e.x * a.y), one);
  const SmallPolygon* region = &one;
  if (half_plane) {
    clipSmallPolygon(one, slope, offset, two);
    region = &two;
  }
  const dvec3 fraction = polygonFraction(region->v, region->n);
  return turn > 0.0 ? fraction : -fraction;
}

dvec3 TexturedSquare::halfPlaneFraction(dvec2 slope, double offset, bool flip_y) const {
  if (flip_y) slope.y = -slope.y;
  SmallPolygon region;
  clipSmallPolygon(square(), slope, offset, region);
  return polygonFraction(region.v, region.n);
}

}  // namespace penumbra
