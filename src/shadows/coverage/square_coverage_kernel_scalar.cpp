// Scalar twin of square_coverage_kernel_simd.cpp (square_coverage_kernel.h gives the formulas).
#include <cmath>

#include "shadows/coverage/square_coverage_kernel.h"

namespace penumbra {

namespace {

// The cone's triangle on the side x = 1: (s_hi - s_lo) / 2 over the s in [-1, 1] with
// cross(a, (1, s)) = ax s - ay >= 0 and cross((1, s), b) = by - s bx >= 0.
float sideArea(float ax, float ay, float bx, float by) {
  const float ra = ay / (ax != 0.0f ? ax : 1.0f);
  const float rb = by / (bx != 0.0f ? bx : 1.0f);
  float lo = -1.0f, hi = 1.0f;
  if (ax > 0.0f) lo = ra > lo ? ra : lo;
  if (ax < 0.0f) hi = ra < hi ? ra : hi;
  if (bx > 0.0f) hi = rb < hi ? rb : hi;
  if (bx < 0.0f) lo = rb > lo ? rb : lo;
  const bool open = (ax != 0.0f || ay <= 0.0f) && (bx != 0.0f || by >= 0.0f);
  const float width = hi - lo;
  return open && width > 0.0f ? width * 0.5f : 0.0f;
}

}  // namespace

float squareCoverageOne(float x0, float y0, float w0, float x1, float y1, float w1) {
  FrontSegment s;
  if (!frontSegment(x0, y0, w0, x1, y1, w1, s)) return 0.0f;
  const float ax = s.ax, ay = s.ay, aw = s.aw, bx = s.bx, by = s.by, bw = s.bw;
  const float l1 = s.l1, l2 = s.l2, l3 = s.l3;
  const float n2 = l1 * l1 + l2 * l2;
  if (!(n2 > 0.0f) || l3 == 0.0f) return 0.0f;  // a point, or a line through the centre
  const float inv_n = 1.0f / std::sqrt(n2);
  const float ux = l2 * inv_n, uy = -l1 * inv_n;
  const float dist = l3 * inv_n;  // signed distance of the line from the centre
  const float mx = -(dist * (l1 * inv_n)), my = -(dist * (l2 * inv_n));
  float lo = (ax * ux + ay * uy) / aw;
  float hi = (bx * ux + by * uy) / bw;
  // Slabs |m + s u| <= 1, x then y.
  const float cx0 = (-1.0f - mx) / (ux != 0.0f ? ux : 1.0f);
  const float cx1 = (1.0f - mx) / (ux != 0.0f ? ux : 1.0f);
  if (ux != 0.0f) {
    const float near = cx0 < cx1 ? cx0 : cx1, far = cx0 < cx1 ? cx1 : cx0;
    lo = near > lo ? near : lo;
    hi = far < hi ? far : hi;
  } else if (!(std::fabs(mx) <= 1.0f)) {
    return 0.0f;
  }
  const float cy0 = (-1.0f - my) / (uy != 0.0f ? uy : 1.0f);
  const float cy1 = (1.0f - my) / (uy != 0.0f ? uy : 1.0f);
  if (uy != 0.0f) {
    const float near = cy0 < cy1 ? cy0 : cy1, far = cy0 < cy1 ? cy1 : cy0;
    lo = near > lo ? near : lo;
    hi = far < hi ? far : hi;
  } else if (!(std::fabs(my) <= 1.0f)) {
    return 0.0f;
  }
  if (!(hi > lo)) return 0.0f;
  const float q0x = mx + lo * ux, q0y = my + lo * uy;
  const float q1x = mx + hi * ux, q1y = my + hi * uy;
  // Counter-clockwise: a then b (the turn from q0 to q1 has the sign of l3).
  const bool ccw = l3 > 0.0f;
  float pax = ccw ? q0x : q1x, pay = ccw ? q0y : q1y;
  float pbx = ccw ? q1x : q0x, pby = ccw ? q1y : q0y;
  const float triangle = (pax * pby - pay * pbx) * 0.5f;
  float cone = 0.0f;
  for (int side = 0; side < 4; ++side) {
    cone = cone + sideArea(pax, pay, pbx, pby);
    // Turn both a quarter clockwise: the next side of the square becomes x = 1.
    const float tax = pay, tay = -pax, tbx = pby, tby = -pbx;
    pax = tax, pay = tay, pbx = tbx, pby = tby;
  }
  const float fraction = (cone - triangle) * 0.25f;
  return ccw ? fraction : -fraction;
}

void squareCoverageScalar(const DiskCoverageBatch& b, size_t n) {
  for (size_t i = 0; i < n; ++i)
    b.fraction[i] = squareCoverageOne(b.x0[i], b.y0[i], b.w0[i], b.x1[i], b.y1[i], b.w1[i]);
}

}  // namespace penumbra
