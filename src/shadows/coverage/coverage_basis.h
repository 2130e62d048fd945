#pragma once
// The light as one visible point sees it, for the coverage soft shadow volumes: the basis of
// the light's plane in which the light is the unit disk or the square [-1, 1]^2 (shape_coverage.h)
// and edge end points become homogeneous 2D points (disk_coverage_kernel.h).
//
// A sphere of radius r at distance D is taken as the disk its tangent cone cuts out of the
// plane through its centre facing the point, radius r D / sqrt(D^2 - r^2): the outline the
// oracle's rays fill, uniform in that disk's area where the oracle is uniform in solid angle
// (Funk 2004, section 3.1.2, takes the disk of radius r and also calls the difference
// negligible). A disk or rectangle light is its own plane, seen from either side.
// The basis (t, b, n) is right-handed with n from the point toward the light's plane,
// so that every shape turns the same way (the edge's sign, coverage_technique.cpp).
#include "core/math.h"
#include "scene/light.h"
#include "shadows/coverage/shape_coverage.h"

namespace penumbra {

struct CoverageBasis {
  dvec3 p{0.0};
  dvec3 t{0.0}, b{0.0}, n{0.0};
  double inv_depth = 0.0;     // 1 / n . (c - p)
  double offset_t = 0.0, offset_b = 0.0;  // (p - c) . t, (p - c) . b
  double scale_t = 1.0, scale_b = 1.0;    // to the unit disk or square
  LightOutline outline = LightOutline::Disk;

  // (X, Y, W) of a world point: W = n . (x - p) / n . (c - p), and X, Y its projection's
  // position on the plane times W.
  dvec3 homogeneous(const dvec3& x) const {
    const dvec3 rel = x - p;
    const double w = glm::dot(n, rel) * inv_depth;
    return dvec3((glm::dot(rel, t) + w * offset_t) * scale_t,
                 (glm::dot(rel, b) + w * offset_b) * scale_b, w);
  }
};

// Fraction of the light in front of the plane through the point with normal `normal` (the side
// it points to): what the point's own surface leaves of the light.
double frontOfPlaneFraction(const CoverageBasis& basis, const dvec3& normal);
// The same plane as a half-plane of the basis's light plane: slope . (X, Y) + offset > 0 in front.
void frontHalfPlane(const CoverageBasis& basis, const dvec3& normal, dvec2& slope, double& offset);

// False when the point sees the light from inside it (a sphere) or edge-on (in a disk's or
// rectangle's plane): no edge coverage is defined there and the hard answer stands.
bool coverageBasis(const Light& light, const dvec3& p, CoverageBasis& basis);

}  // namespace penumbra
