#pragma once
// Penumbra wedges (2002 paper, section 4.1) built from the silhouette seen from the light
// centre, and the light intensity inside them (section 4.2).
//
// Numeric conventions: all wedge geometry is double precision world space (the mesh and the
// light are float; they are widened once). Plane values are signed distances (unit normals).
// The umbra quads' points at infinity are float directions, homogeneous w = 0, as in the hard
// shadow volume (shadows/stages/caster_volumes/caster_volume.h).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/light.h"
#include "scene/mesh.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {

// A plane n.x + d = 0 with unit n; a point is inside when n.x + d >= 0.
struct Plane {
  dvec3 n{0.0};
  double d = 0.0;
  double eval(const dvec3& p) const { return glm::dot(n, p) + d; }
};

inline constexpr uint32_t kNoWedgeLink = 0xFFFFFFFFu;

// Per-wedge constants of equations (2)-(3): every distance t in those equations is a plane
// value at p divided by |plane normal . ray direction|, and these are the divisors. They depend
// on the wedge only, so the rasterizer computes them once per wedge (section 5: "reciprocal dot
// products ... precomputed at setup").
struct WedgeIntensityConstants {
  double front_left = 1.0, back_left = 1.0;    // |front.n . dir_left|, |back.n . dir_left|
  double front_right = 1.0, back_right = 1.0;  // |front.n . dir_right|, |back.n . dir_right|
  double left = 1.0, right = 1.0;              // |left.n . edge_dir|, |right.n . edge_dir|
};

// One wedge per unit of silhouette multiplicity (SilhouetteEdge::multiplicity; closed meshes
// have 1, two-sided open ones may have 2 where two sheets share an edge), except the nearly
// parallel edges (WedgeOptions::parallel_degrees), which get an umbra quad but no wedge.
struct Wedge {
  // The silhouette edge oriented a -> b so that the hard shadow-volume quad (b, a, a', b') (primes:
  // extruded to infinity) faces out of the shadow (shadows/stages/silhouettes/silhouette.h).
  uint32_t va = 0, vb = 0;  // mesh vertex indices
  dvec3 a{0.0}, b{0.0};     // positions (world)
  // Inward planes: front (through a, b and f = c - r n), back (through a, b and c + r n, the
  // paper's point b), n the unit normal of the shadow-volume quad pointing out of the shadow;
  // left through a, right through b, each shared with the adjacent wedge (section 4.1, Figure
  // 5): the right plane of a wedge is bit for bit the negated left plane of
  // wedges[right_wedge].
  // The wedge lies between the front plane (outer, lit side: s = 1) and the back plane (inner,
  // umbra side: s = 0); the light centre is outside both (eval < 0) when r > 0.
  Plane front, back, left, right;
  // Unit side-plane ray directions for equation (2): the average of the two adjacent quad
  // normals projected into the side plane (section 4.1, last paragraph before Figure 7). They
  // point toward the lit side, across the wedge; only their line matters, since equation (2)
  // uses unsigned distances. Shared bit for bit with the adjacent wedge.
  dvec3 dir_left{0.0}, dir_right{0.0};
  dvec3 edge_dir{0.0};  // unit a -> b, the direction of t_l, t_r in equation (3)
  dvec3 normal{0.0};    // n: unit normal of the hard shadow-volume quad, out of the shadow
  // The wedge polyhedron for rasterization: unbounded edges from a (left) and b (right) along
  // the front/side and back/side plane intersections, unit directions away from the light.
  // With r > 0 the umbra quad's directions are always vec3(ray_front_left / right), so the
  // front face is exactly the umbra quad. Where the side plane is shared at one vertex (the
  // neighbour's a is this wedge's b), the neighbour's rays there are the same vectors, bit for
  // bit; across a run of nearly parallel edges the neighbour starts at another vertex and has
  // its own rays in the shared plane; at a split or unpaired end there is no neighbour.
  dvec3 ray_front_left{0.0}, ray_front_right{0.0}, ray_back_left{0.0}, ray_back_right{0.0};
  // Section 4.1, Figure 6: when the side planes cross inside the wedge the wedge is cut by a
  // bottom plane before the crossing, and the four rays end at the far_* points (valid only
  // when finite). The polyhedron then has the faces front (a, b, far_front_right,
  // far_front_left), back (a, b, far_back_right, far_back_left), left (a, far_front_left,
  // far_back_left), right (b, far_front_right, far_back_right) and bottom (the four far_*).
  // Diagnostic only: rendering and insideWedge use the four planes, which close the wedge
  // where the side planes meet (light_wedges.cpp says why).
  bool finite = false;
  Plane bottom;
  dvec3 far_front_left{0.0}, far_front_right{0.0}, far_back_left{0.0}, far_back_right{0.0};
  // No interior: the light radius is 0 (front and back are the same plane, negated) or no
  // convex polyhedron could be made (WedgeSet::degenerate_wedges). insideWedge is false
  // everywhere; the wedge's umbra quad still counts, so the penumbra pass may skip it.
  bool flat = false;
  uint32_t unit_edge = 0;  // index of this wedge's quad in WedgeSet::umbra
  // The wedges sharing the left / right plane (indices into WedgeSet::wedges), or kNoWedgeLink
  // where the wedge ends on its own plane: a split vertex or an unpaired end (wedge.cpp). (A
  // gap wedge at a split vertex shares the plane but is not linked from here: gap_wedges.)
  uint32_t left_wedge = kNoWedgeLink, right_wedge = kNoWedgeLink;
};

// The umbra volume's side: the front-plane quad of each unit silhouette edge (a, b, and the points
// at infinity along the front-plane/side-plane lines), which the 2004 paper (section 3) rasterizes
// with -255 before the wedges add 255 s back. Like the hard quad it is the polygon (b, a, a + inf_a
// at w = 0, b + inf_b at w = 0) facing out of the umbra volume, drawn as two triangles as in
// shadows/stages/stencil/shadow_stencil.cpp. The first quads are those of the unit silhouette edges
// (index = Wedge::unit_edge); after them come connectors, one per split vertex where two wedges
// meet (WedgeSet::split_vertices, except splits across parallel runs): va == vb, so only the
// triangle (v, v + inf_a, v + inf_b) at infinity has area, fanning between the two wedges' front
// rays there. Invariant: every pairing's direction is shared bit for bit by the two quads it joins
// (umbra[q].inf_b == umbra[umbra[q].next].inf_a), so the volume stays closed. With a zero radius
// the directions are exactly vec3(position) - light.center, as in the hard shadow volume
// (shadows/stages/caster_volumes/caster_volume.h), so the umbra is then the hard shadow volume bit
// for bit.
struct UmbraQuad {
  uint32_t va = 0, vb = 0;        // a -> b as in Wedge
  vec3 inf_a{0.0f}, inf_b{0.0f};  // homogeneous w = 0 points: directions from a and from b
  // The quads joined to this one at a and at b (indices into WedgeSet::umbra), or kNoWedgeLink
  // where the silhouette loop is broken.
  uint32_t prev = kNoWedgeLink, next = kNoWedgeLink;
  // False for nearly parallel edges and connectors: no edge wedge has this quad as its front
  // face (a connector's gap wedge, WedgeSet::gap_wedges, draws its own front face over it).
  bool has_wedge = true;
};

// The 2002 paper's optional extra wedges around acute silhouette vertices (section 4.1,
// Figure 7) are not built, and no option builds them: a corner whose shared side plane does
// not fit is split, and the notch the two end planes leave gets one gap wedge (wedge_gap.h).
// The README's "Differences from the papers" says why the fans were measured and left out.
struct WedgeBuildOptions {
  // Edges within this angle (degrees, in [0, 90)) of the direction to the light at either end
  // are "nearly parallel" (section 8): they get no penumbra wedge and their neighbours are
  // reconnected (wedge.cpp). Edges through the light centre are always treated so.
  double parallel_degrees = 2.0;
};

struct WedgeSet {
  std::vector<Wedge> wedges;
  // One per unit silhouette edge (including nearly parallel ones), then the connectors.
  std::vector<UmbraQuad> umbra;
  // Diagnostics.
  size_t junction_vertices = 0;       // silhouette vertices with more than two silhouette edges
  size_t parallel_edges_removed = 0;  // unit edges without a wedge (nearly parallel)
  size_t finite_wedges = 0;
  size_t degenerate_wedges = 0;  // r > 0 but flat: no convex polyhedron could be made
  size_t unpaired_ends = 0;      // wedge ends closed by a lone side plane (broken loops)
  // Pairings whose shared side plane would not fit both wedges (acute corners, wedge.cpp):
  // each wedge ends on its own plane there and a connector umbra quad joins them.
  size_t split_vertices = 0;
  // One per split vertex where the two wedges leave a notch between their end planes: a cone
  // with its apex at the vertex (a == b), front face the connector fan, sides the two end
  // planes negated (wedge_gap.h). Its left_wedge / right_wedge index `wedges`, its unit_edge
  // is the connector's quad. Kept apart from `wedges`, whose every entry has a silhouette edge
  // and a front face that is its own unit edge's quad.
  std::vector<Wedge> gap_wedges;
};

// Throws penumbra::Error for a light with a negative or non-finite radius or centre, a
// parallel_degrees outside [0, 90), or a silhouette
// vertex out of range or not finite.
WedgeSet buildWedges(const Mesh& mesh, const Silhouette& silhouette, const Light& light,
                     const WedgeBuildOptions& options = {});

enum class Falloff {
  Linear,  // equations (2)-(3)
  Smooth,  // s' = 3 s^2 - 2 s^3 (Parker et al., cited in section 4.2)
};

WedgeIntensityConstants wedgeIntensityConstants(const Wedge& wedge);

// Equations (2)-(3) from the four plane values at p (front f, back b, left l, right r), in the
// one-division form (least common denominator, section 4.2): with t_lf = f / front_left etc.,
//   s = b (r L Fl Dr + l R Fr Dl) / ((r L + l R) Dl Dr),  Dl = f Bl + b Fl,  Dr = f Br + b Fr
// (L = left, R = right, Fl = front_left, Bl = back_left, ... of the constants). It is
// homogeneous of degree 0 in (f, b, l, r): multiplying all four by one positive factor leaves s
// unchanged, so screen-space plane values (world values times a positive per-pixel factor) can
// be passed directly. Negative values (points just outside) count as 0; where a ratio is 0/0
// (on the edge line, or on the line where the side planes meet) the two sides are averaged.
// Returns s in [0, 1], linear falloff.
double intensityFromPlaneValues(const WedgeIntensityConstants& k, double f, double b, double l,
                                double r);

// Applies the falloff to a linear intensity s in [0, 1].
double applyFalloff(double s, Falloff falloff);

// Light intensity s in [0, 1] of a point inside the wedge (equations (2)-(3)); 1 on the front
// plane, 0 on the back plane, continuous across the shared side planes of adjacent wedges.
double wedgeIntensity(const Wedge& wedge, const dvec3& p, Falloff falloff = Falloff::Linear);
// Whether p is inside all four planes of a wedge that is not flat: the region the penumbra
// passes rasterize (light_wedges.cpp). The Figure 6 bottom cut (finite, bottom) is not applied.
bool insideWedge(const Wedge& wedge, const dvec3& p);

}  // namespace penumbra
