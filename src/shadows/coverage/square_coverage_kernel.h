#pragma once
// The per-edge coverage of a rectangle light, the float kernel with a SIMD twin (the disk's is
// disk_coverage_kernel.h, which gives the input form and the line clip). The rectangle is
// scaled to the square [-1, 1]^2 (shape_coverage.h). After the cut to W >= kMinDepth and the
// line form (point m closest to the centre, unit direction u), the chord is clipped to the
// square by its two slabs, |m + s u| <= 1 per axis, and with its ends ordered counter-clockwise
// around the centre, a then b,
//   area = (square inside the cone from the centre between a and b) - triangle (0, a, b) / 2,
// the cone's part found side by side: on the side x = 1 the points (1, s) with
// cross(a, (1, s)) >= 0 and cross((1, s), b) >= 0 form an interval of s, and the cone's
// triangle on that side has area (s_hi - s_lo) / 2; the other three sides are the same with a
// and b turned by a quarter each time. Signed by the turn (l3), over 4.
// Float, in exactly this order in the kernel and its scalar twin (no FMA: -ffp-contract=off).
#include <cstddef>

#include "shadows/coverage/disk_coverage_kernel.h"

namespace penumbra {

// Same batch layout as the disk's; `fraction` gets the signed fraction of the square.
void squareCoverage(const DiskCoverageBatch& batch, size_t n, bool simd);
void squareCoverageScalar(const DiskCoverageBatch& batch, size_t n);
float squareCoverageOne(float x0, float y0, float w0, float x1, float y1, float w1);

}  // namespace penumbra
