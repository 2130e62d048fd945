#pragma once
// The hot loop of the coverage soft shadow volumes (`coverage`): for a batch of (pixel,
// silhouette edge) pairs, the signed fraction of a disk-shaped light that the edge's hard
// shadow quad covers as seen from the pixel's point (the 2003 soft shadow volumes' per-edge
// coverage; Funk 2004, section 3.1.3: "the pie section between the clipped points minus the
// triangle they make with the centre").
//
// Input per pair: the edge's end points a, b projected from the point onto the light's plane,
// in homogeneous 2D coordinates (X, Y, W) of the plane's basis scaled so that the light is the
// unit disk around the origin: W = 1 on the light's plane, 0 at the point, negative behind it
// (coverage_technique.cpp sets them up in double). The segment is first cut to W >= kMinDepth
// (the part in front of the point), then
//   its line l = P0 x P1 = (l1, l2, l3): distance from the centre d = |l3| / |(l1, l2)|, unit
//   direction u = (l2, -l1) / |(l1, l2)| from P0 to P1, positions along it s = (P . u) / W;
//   clipped to the disk: [s_lo, s_hi] = [s0, s1] intersected with [-h, h], h = sqrt(1 - d^2);
//   area beyond the chord inside the cone from the centre over it (sector minus triangle):
//     A = (atan2(s_hi, d) - atan2(s_lo, d) - (s_hi - s_lo) d) / 2,
//   signed by l3 (the side of the hard quad's plane the point is on: the quad holds the light
//   centre and the edge, so l3 = 0 exactly when the point is on that plane), over pi.
// The line form keeps the clip exact when an end point projects far outside (W near 0): only
// the end point's s grows, and it is clamped to [-h, h], never subtracted.
//
// Everything is float, in exactly the order written in coverage_kernel_scalar.cpp; atan is a
// polynomial of our own (same operations in both), so the SIMD kernel and its scalar twin give
// the same bits (the build passes -ffp-contract=off).
#include <cstddef>

namespace penumbra {

inline constexpr float kMinDepth = 1e-4f;  // W below which an edge point is cut away

// The scalar twins' shared front end (disk and square): the edge's end points cut to
// W >= kMinDepth, A = (ax, ay, aw) and B = (bx, by, bw), and the line through them, l = A x B.
// False when nothing of the edge is in front of the point.
struct FrontSegment {
  float ax, ay, aw, bx, by, bw;
  float l1, l2, l3;
};
inline bool frontSegment(float x0, float y0, float w0, float x1, float y1, float w1,
                         FrontSegment& s) {
  const bool keep0 = w0 >= kMinDepth, keep1 = w1 >= kMinDepth;
  if (!keep0 && !keep1) return false;
  const float dw = w1 - w0;
  const float tc = (kMinDepth - w0) / (keep0 && keep1 ? 1.0f : dw);
  const float t0 = keep0 ? 0.0f : tc;
  const float t1 = keep1 ? 1.0f : tc;
  const float dx = x1 - x0, dy = y1 - y0;
  s.ax = x0 + t0 * dx;
  s.ay = y0 + t0 * dy;
  s.aw = keep0 ? w0 : kMinDepth;
  s.bx = x0 + t1 * dx;
  s.by = y0 + t1 * dy;
  s.bw = keep1 ? w1 : kMinDepth;
  s.l1 = s.ay * s.bw - s.aw * s.by;
  s.l2 = s.aw * s.bx - s.ax * s.bw;
  s.l3 = s.ax * s.by - s.ay * s.bx;
  return true;
}

// Batches are structure-of-arrays, n entries each, any n (no alignment needed).
struct DiskCoverageBatch {
  const float *x0, *y0, *w0, *x1, *y1, *w1;
  float* fraction;  // out: signed covered fraction of the disk, in [-1, 1]
};

void diskCoverage(const DiskCoverageBatch& batch, size_t n, bool simd);
void diskCoverageScalar(const DiskCoverageBatch& batch, size_t n);

// The one pair of the scalar twin (also the reference the tests hold the table to).
float diskCoverageOne(float x0, float y0, float w0, float x1, float y1, float w1);

// atan(x) for |x| <= 1, a degree-11 odd minimax polynomial (absolute error below 2e-6 rad),
// Horner form in this order in both kernels.
inline float atanUnit(float x) {
  const float x2 = x * x;
  float p = -0.0117212f;
  p = p * x2 + 0.05265332f;
  p = p * x2 + -0.11643287f;
  p = p * x2 + 0.19354346f;
  p = p * x2 + -0.33262347f;
  p = p * x2 + 0.99997726f;
  return p * x;
}

}  // namespace penumbra
