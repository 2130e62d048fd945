#pragma once
// Internal to the wedge builder: front and back planes of one edge, the side planes where two
// wedges meet (2002 paper, section 4.1, Figure 5), and the finite cut of Figure 6.
//
// Numeric conventions: double precision world space; c is the light centre, r its radius;
// `hard` arguments are the unit hard-shadow directions normalize(vec3(v) - light.center)
// (computed from the float difference, as the hard volume is), used whenever r == 0.
#include "core/math.h"
#include "shadows/wedge/wedge.h"
#include "shadows/wedge/wedge_pairing.h"

namespace penumbra::wedge_detail {

// Two unit vectors (rays, plane normals) whose cross product is shorter than this count as
// parallel: the plane through them, or the line where they meet, would be rounding noise
// (normals carry ~1e-16 of error).
inline constexpr double kParallelSin = 1e-9;

struct EdgePlanes {
  Plane front, back;  // inward: the wedge lies on the positive side of both
};

// Front plane through a, b, f = c - r n; back plane through a, b, c + r n (section 4.1). With
// r == 0 both are the hard quad's plane and back is front negated exactly.
EdgePlanes edgePlanes(const UnitEdge& e, const dvec3& c, double r);

// A side plane oriented inward for the wedge that ends at it (its right plane); the wedge that
// starts at it uses it negated. Rays are unit, away from the light: `*_in` those of the ending
// wedge (front/back plane with the side plane), `*_out` those of the starting wedge; they are
// the same vectors at an ordinary vertex.
struct SidePlane {
  Plane plane;
  dvec3 dir{0.0};  // equation (2) direction, in the plane
  dvec3 front_in{0.0}, back_in{0.0}, front_out{0.0}, back_out{0.0};
};

// Ordinary vertex v where `in` ends and `out` starts: the plane through v and the lines where
// the two front planes and the two back planes meet (Figure 5).
SidePlane regularSide(const UnitEdge& in, const EdgePlanes& pin, const UnitEdge& out,
                      const EdgePlanes& pout, const dvec3& c, double r, const dvec3& hard);

// `in` ends at v = in.b, `out` starts at w = out.a, and a run of nearly parallel edges joins
// them: one plane through v and w (see wedge.cpp for why).
SidePlane bridgedSide(const UnitEdge& in, const EdgePlanes& pin, const UnitEdge& out,
                      const EdgePlanes& pout, const dvec3& c, double r, const dvec3& hard_v,
                      const dvec3& hard_w);

// An end with no partner: the plane through the end vertex and the light's diameter along n
// (it contains f and c + r n), oriented inward for `e`; the rays are in the `*_in` fields.
SidePlane loneSide(const UnitEdge& e, bool at_b, const dvec3& c, double r, const dvec3& hard);

// Whether a side plane (oriented inward for `e`, at its b end if at_b, else at its a end) and
// the rays it gives `e` make a usable wedge end: the front ray must leave the edge into the
// back plane's inside and the back ray into the front plane's inside (they run along the edge
// line, or behind it, at acute silhouette corners that are also steep to the light), the
// plane must not hold the edge itself, and both rays must stay within twice the light's
// angular radius of the hard direction v - c (acute corners push the shared lines far out).
// Always true with r == 0 (flat wedges).
bool sideFits(const UnitEdge& e, const EdgePlanes& planes, const Plane& inward,
              const dvec3& ray_front, const dvec3& ray_back, bool at_b, const dvec3& c, double r);

// Figure 6: when a ray of the wedge leaves it through the opposite side plane (the side planes
// cross inside the wedge), cuts the wedge with a bottom plane before the first crossing and
// sets finite, bottom and far_*. Returns false when no convex five-faced polyhedron can be
// made (the side planes cross at the edge itself); the wedge is left unchanged then.
bool cutWhereSidesCross(Wedge& wedge, const dvec3& c);

}  // namespace penumbra::wedge_detail
