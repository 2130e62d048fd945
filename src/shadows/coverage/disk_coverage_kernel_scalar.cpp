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
  // Cut to the part in front of the point (W >= kMinDepth); the line through both ends.
  FrontSegment s;
  if (!frontSegment(x0, y0, w0, x1, y1, w1, s)) return 0.0f;
  const float ax = s.ax, ay = s.ay, aw = s.aw, bx = s.bx, by = s.by, bw = s.bw;
  const float l1 = s.l1, l2 = s.l2, l3 = s.l3;
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
