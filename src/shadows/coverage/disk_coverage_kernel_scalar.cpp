// Scalar twin of disk_coverage_kernel_simd.cpp: the same float operations in the same order
// (disk_coverage_kernel.h gives the formulas).
#include <cmath>

#include "shadows/coverage/disk_coverage_kernel.h"

namespace penumbra {

namespace {
constexpr float kHalfPi = 1.57079632679489662f;
constexpr float kInvPi = 0.318309886183790672f;

// atan2(s, d) for d >= 0: atanUnit of the smaller over the larger, reflected about pi/4.
float angleOf(float s, float d) {
  const float a = std::fabs(s);
  const float big = a > d ? a : d;
  const float small = a > d ? d : a;
  const float ratio = big > 0.0f ? small / big : 0.0f;
  const float t = atanUnit(ratio);
  const float r = a > d ? kHalfPi - t : t;
  return s < 0.0f ? -r : r;
}
}  // namespace

float diskCoverageOne(float x0, float y0, float w0, float x1, float y1, float w1) {
  // Cut to the part in front of the point: W >= kMinDepth.
  const bool keep0 = w0 >= kMinDepth, keep1 = w1 >= kMinDepth;
  if (!keep0 && !keep1) return 0.0f;
  const float dw = w1 - w0;
  const float tc = (kMinDepth - w0) / (keep0 && keep1 ? 1.0f : dw);
  const float t0 = keep0 ? 0.0f : tc;
  const float t1 = keep1 ? 1.0f : tc;
  const float dx = x1 - x0, dy = y1 - y0;
  const float ax = x0 + t0 * dx, ay = y0 + t0 * dy, aw = keep0 ? w0 : kMinDepth;
  const float bx = x0 + t1 * dx, by = y0 + t1 * dy, bw = keep1 ? w1 : kMinDepth;
  // The line through both, l = A x B.
  const float l1 = ay * bw - aw * by;
  const float l2 = aw * bx - ax * bw;
  const float l3 = ax * by - ay * bx;
  const float n2 = l1 * l1 + l2 * l2;
  if (!(n2 > 0.0f)) return 0.0f;  // the edge points at the point: no area
  const float inv_n = 1.0f / std::sqrt(n2);
  const float d = std::fabs(l3) * inv_n;
  const float h2 = 1.0f - d * d;
  if (!(h2 > 0.0f)) return 0.0f;  // the line misses the disk
  const float h = std::sqrt(h2);
  const float ux = l2 * inv_n, uy = -l1 * inv_n;
  const float sa = (ax * ux + ay * uy) / aw;
  const float sb = (bx * ux + by * uy) / bw;
  const float lo = sa > -h ? sa : -h;
  const float hi = sb < h ? sb : h;
  if (!(hi > lo)) return 0.0f;  // the segment ends before the disk or starts after it
  const float area = ((angleOf(hi, d) - angleOf(lo, d)) - (hi - lo) * d) * 0.5f;
  const float fraction = area * kInvPi;
  return l3 < 0.0f ? -fraction : fraction;
}

void diskCoverageScalar(const DiskCoverageBatch& b, size_t n) {
  for (size_t i = 0; i < n; ++i)
    b.fraction[i] = diskCoverageOne(b.x0[i], b.y0[i], b.w0[i], b.x1[i], b.y1[i], b.w1[i]);
}

}  // namespace penumbra
