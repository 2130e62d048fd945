#pragma once
// The hot loop of the exact soft shadow volumes: one silhouette edge's change to the depth
// complexity of every light sample of one pixel (docs/exact-soft-shadows.md, "Per pixel").
//
// Samples are points (x, y) of the plane tangent to the light's direction cone at unit distance
// from the pixel's point, in the cone's basis (light_sampling.h): the light centre is (0, 0).
// The edge, projected from the point, is a segment a'b' on that plane. A sample s changes by
// `delta` exactly when the segment from the centre to s crosses a'b', that is when s lies
//   - inside the sector from the centre spanned by a' and b': on the `a_side` of the line
//     through the centre and a' (sector_a), and on the `b_side` of the one through b'
//     (sector_b); a sample on such a line counts as on its positive side (>= 0), whichever edge
//     asks, so two edges sharing a vertex never both count it nor both miss it;
//   - and on the other side of the edge's line (line) than the centre (centre_side).
// Lines are evaluated in float, in exactly this order, by the SIMD kernel and its scalar twin
// (no FMA: the build passes -ffp-contract=off), so both give the same counts.
#include <cstddef>
#include <cstdint>

namespace penumbra {

struct SampleEdge {
  float sector_a[2], sector_b[2];  // through the centre: value = v[0] x + v[1] y
  float line[3];                   // value = (v[0] x + v[1] y) + v[2]
  bool a_side, b_side, centre_side;  // true: the side where the value is >= 0
  int32_t delta;
};

// Adds edge.delta to count[i] for every sample i in [0, n) the edge crosses; x, y and count
// hold n entries, n a multiple of kSampleBlock, and are aligned to kSampleAlignment bytes.
inline constexpr size_t kSampleBlock = 16;
inline constexpr size_t kSampleAlignment = 64;
// The samples of one point on its plane at unit distance: sample i at polar radius^2
// radius2[i] of the unit disk and angle (cos_phi[i], sin_phi[i]) takes the cone angle theta
// with 1 - cos(theta) = radius2[i] * one_minus_cos_max (uniform in solid angle over the cap,
// as the oracle's sampleSphereCone) and lands at tan(theta) (cos_phi, sin_phi). Same layout
// rules as addEdgeCrossings for x and y (the inputs need no alignment).
void samplePositions(const float* radius2, const float* cos_phi, const float* sin_phi,
                     float one_minus_cos_max, float* x, float* y, size_t n, bool simd);
void samplePositionsScalar(const float* radius2, const float* cos_phi, const float* sin_phi,
                           float one_minus_cos_max, float* x, float* y, size_t n);

void addEdgeCrossings(const SampleEdge& edge, const float* x, const float* y, int32_t* count,
                      size_t n, bool simd);
void addEdgeCrossingsScalar(const SampleEdge& edge, const float* x, const float* y,
                            int32_t* count, size_t n);

}  // namespace penumbra
