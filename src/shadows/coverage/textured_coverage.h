#pragma once
// Per-edge coverage of a textured rectangle light (light.h, LightTexture; issue 9 item 3, the
// 2003 algorithm's textured lights), exact and per colour channel: the texture-weighted share
// of the light in the region an edge covers, where shape_coverage.h has the area share.
//
// In the coverage basis's square [-1, 1]^2 (shape_coverage.h) the region beyond a segment a-b
// (ordered counter-clockwise around the centre) is the square cut by three half-planes: the
// cone's two sides through a and b and the chord's far side; the visible surface's plane
// (frontHalfPlane) cuts it once more at the terminator. Each cut keeps a convex polygon, whose
// texture integral is exact by Green's theorem, integral of T dA = loop integral of F dV with
// F(U, V) the integral of T from the square's side U = 0 to U along the row: in texel units
// (U, V in [0, width] x [0, height]) F is linear between texel borders, so every piece of a
// polygon edge between two texel borders adds (F at its midpoint) x (its dV), with F from
// per-row prefix sums. The cost is the texel borders the polygon's edges cross.
#include <vector>

#include "core/math.h"
#include "scene/light.h"

namespace penumbra {

class TexturedSquare {
 public:
  explicit TexturedSquare(const LightTexture& texture);

  // Signed texture-weighted fraction, per channel, of the light beyond the segment lo-hi (both
  // inside the square), signed as insideFraction (counter-clockwise turn positive); with
  // `half_plane`, only the part where slope . (X, Y) + offset > 0. `flip_y`: the basis's second
  // axis runs against the light's edge v (coverage_basis.h may flip it), so the texture is read
  // mirrored.
  dvec3 beyondFraction(dvec2 lo, dvec2 hi, bool flip_y, bool half_plane, dvec2 slope,
                       double offset) const;
  // Texture-weighted fraction of the light where slope . (X, Y) + offset > 0.
  dvec3 halfPlaneFraction(dvec2 slope, double offset, bool flip_y) const;
  // Integral of the texture over a convex polygon of the square, counter-clockwise, over the
  // whole light's: in [0, 1] per channel.
  dvec3 polygonFraction(const std::vector<dvec2>& polygon) const {
    return polygonFraction(polygon.data(), polygon.size());
  }
  dvec3 polygonFraction(const dvec2* polygon, size_t count) const;

 private:
  int width_, height_;
  std::vector<dvec3> texels_;  // row-major
  std::vector<dvec3> prefix_;  // per row, width + 1 sums: prefix_[j (w + 1) + i] = sum_{k < i}
  dvec3 inv_total_;            // 1 / (sum of all texels) per channel; 0 for a black channel
};

// A convex polygon cut to the half-plane n . x + d >= 0 (Sutherland-Hodgman, one plane); empty
// when less than a triangle is left.
std::vector<dvec2> clipPolygonToHalfPlane(const std::vector<dvec2>& polygon, const dvec2& n,
                                          double d);

// The same on a fixed-capacity polygon, for the per-pixel path (no allocation): the square cut
// by at most four half-planes has at most 8 corners.
struct SmallPolygon {
  static constexpr size_t kCapacity = 12;
  dvec2 v[kCapacity];
  size_t n = 0;
};
void clipSmallPolygon(const SmallPolygon& in, const dvec2& normal, double d, SmallPolygon& out);

}  // namespace penumbra
