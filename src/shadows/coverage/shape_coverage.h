#pragma once
// Per-edge covered fraction of the light in double, for every light shape: the reference the
// float disk kernel (disk_coverage_kernel.h) and the coverage table are measured against, and
// the rectangle's path (polygon clipping, scalar in both modes).
//
// The light lies on its plane as the unit disk or the square [-1, 1]^2 around the origin (the
// light centre): a rectangle is scaled to the square per axis, which maps the region beyond an
// edge to the region beyond the mapped edge and keeps area ratios. A segment from a to b on
// that plane covers the part of the light beyond it seen from the centre: the points x of the
// light whose segment from the centre crosses a-b (Funk 2004, Figure 2: the projected hard
// quad). Its area over the light's, signed by the turn a -> b makes around the centre
// (positive counter-clockwise), is the edge's coverage.
#include "core/math.h"

namespace penumbra {

enum class LightOutline { Disk, Square };

// Signed covered fraction for a segment given by its end points on the plane.
double beyondFraction(LightOutline outline, const dvec2& a, const dvec2& b);

// The same for homogeneous end points (X, Y, W): W = 1 on the light's plane, 0 at the point the
// light is seen from (disk_coverage_kernel.h); the part with W < kMinDepth is cut away first.
double beyondFractionHomogeneous(LightOutline outline, const dvec3& a, const dvec3& b);

// The end points of the segment clipped to the light, or false when it misses it (as above).
bool clipToOutline(LightOutline outline, const dvec3& a, const dvec3& b, dvec2& lo, dvec2& hi);

// Signed covered fraction of a segment already inside the light (both ends in it).
double insideFraction(LightOutline outline, const dvec2& lo, const dvec2& hi);

// Fraction of the light where n.x * X + n.y * Y + offset > 0 (a half-plane of the light's plane):
// a circular segment's area for the disk, the clipped square's for the square.
double halfPlaneFraction(LightOutline outline, const dvec2& n, double offset);

// insideFraction restricted to that half-plane: the signed area of the part of the light beyond
// the segment (both ends in the light) and on the kept side, over the whole light's area. With
// the visible surface's own plane as the half-plane (frontOfPlane in coverage_basis.h) the edge
// terms count only the light the surface does not already hide.
double insideFractionInHalfPlane(LightOutline outline, const dvec2& lo, const dvec2& hi,
                                 const dvec2& n, double offset);

}  // namespace penumbra
