#pragma once
// Silhouette extraction from a point (the light centre), shared by shadow volumes and wedges.
//
// Which triangles cast (CasterPolicy):
// - An open or non-manifold mesh: every triangle not edge-on to the light, those facing away
//   from it cast as if flipped ("two-sided casters"). The shadow count of a point is then the
//   number of triangles the segment from the light to the point crosses: exactly what a ray
//   cast sees, whatever the mesh's topology or winding.
// - A closed mesh with the light outside: only light-facing triangles. A segment that crosses
//   the surface enters it first, so the count is non-zero exactly when the two-sided count is,
//   with half the caps and silhouette multiplicity 1 (what penumbra wedges need, 2002 paper
//   section 4: one wedge per silhouette edge).
// - A closed mesh with the light inside: only the triangles facing away from it, flipped
//   (light-facing ones would cast nothing and every outside point would wrongly be lit).
// - SolidWithHoles, for penumbra wedges (below): an open mesh is taken as a solid with holes.
// - SolidWithHoles also casts a triangle exactly edge-on to the light centre with the chosen
//   facing; the other facing is drawn apart (edge_on_sheet.h).
// Per undirected edge the signed uses of the casting triangles are summed (edges.h): shared
// edges of two same-facing triangles cancel, an open edge sums to +-1, an edge of three
// triangles to whatever keeps the volume closed. Doom 3 BFG pairs directed edges the same way.
#include <cstdint>
#include <vector>

#include "scene/edges.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace penumbra {

struct SilhouetteEdge {
  uint32_t v0, v1;  // welded vertex indices, v0 < v1
  // Net number of casting triangles traversing v0 -> v1 (negative: v1 -> v0). The volume side
  // quad (v1, v0, v0 at infinity, v1 at infinity) faces out of the shadow with this weight.
  int32_t multiplicity;
  uint32_t edge;  // its index in the mesh's EdgeAdjacency::edges (which triangles use it)
};

struct Silhouette {
  // Per triangle: +1 casts as wound, -1 casts flipped (faces away from the light), 0 edge-on or
  // degenerate (casts nothing: its volume is empty).
  std::vector<int8_t> orientation;
  std::vector<SilhouetteEdge> edges;
};

enum class CasterPolicy {
  Auto,      // one-sided for closed meshes (by the light's side), two-sided otherwise (above)
  TwoSided,  // every triangle casts, whatever the mesh
  // Penumbra wedges. Two-sided casters give a fold edge (a light-facing triangle meets a
  // facing-away one) multiplicity 2: two coincident wedges, each subtracting the light's
  // covered fraction, so the penumbra reads 1 - 2c instead of 1 - c and its inner half is black
  // (the wedges add per-edge coverage and cannot see overlap, 2002 paper, section 8). So one
  // facing casts, as for a closed mesh, wherever the mesh is consistently oriented (closed or
  // not; non-manifold edges are fine, the per-triangle volumes sum to a closed one anyway): for
  // an open mesh the facing whose triangles cover more of the light's view, which is the
  // light-facing one exactly when the generalized winding number at the light is <= 0
  // (windingNumber). A ray from the light then counts the crossings of that facing only: rays
  // that enter the solid through a hole and leave through its wall (light-facing chosen), or the
  // reverse, are missed, so the inner side of an open mesh seen through a hole can come out lit
  // where a ray cast finds it shadowed. A mesh with inconsistently oriented edges has no
  // meaningful facing and stays two-sided (overlapping penumbrae at its folds included).
  SolidWithHoles,
  // The facing SolidWithHoles leaves out, for open, consistently oriented meshes (closed and
  // inconsistent ones cast as with SolidWithHoles). The wedges draw it in a second pass of
  // their own and keep the darker visibility (wedge_technique.cpp): a ray from a point that
  // crosses a triangle of either facing is blocked, so whichever facing's count is not zero,
  // the point is in the hard shadow, and the rays through a hole that one facing misses, the
  // other counts.
  SolidWithHolesOtherFacing,
};

// Whether the mesh casts differently with SolidWithHolesOtherFacing than with SolidWithHoles
// where it matters: it has open edges (a hole a ray can pass), is consistently oriented and
// has triangles facing the light centre both ways. Judged without its repeated triangles.
bool openMeshWithBothFacings(const Mesh& mesh, const EdgeAdjacency& adjacency, const vec3& light);
// Per mesh of the scene, 1 for such a mesh; empty when there is none. The soft techniques' second
// pass (the other facing) draws exactly these meshes, and runs only when the result is not empty.
std::vector<uint8_t> openMeshesWithBothFacings(const Scene& scene, const vec3& light);

Silhouette findSilhouette(const Mesh& mesh, const EdgeAdjacency& adjacency, const vec3& light,
                          CasterPolicy policy = CasterPolicy::Auto);

// The silhouette edges of triangles cast with `orientation` (one entry per triangle, as
// Silhouette::orientation): per undirected edge the signed uses summed, kept where non-zero.
std::vector<SilhouetteEdge> silhouetteEdges(const EdgeAdjacency& adjacency,
                                            const std::vector<int8_t>& orientation);

// Generalized winding number of the mesh at `point` (Jacobson, Kavan and Sorkine-Hornung 2013):
// the signed solid angle of its triangles seen from there over 4 pi, positive where a triangle
// is seen from its back. 1 inside a closed outward-oriented mesh and 0 outside; for an open
// mesh, (solid angle of the facing-away triangles - that of the light-facing ones) / 4 pi.
// `skip`, when given, is a per-triangle mask of triangles to leave out (repeated ones).
double windingNumber(const Mesh& mesh, const dvec3& point,
                     const std::vector<uint8_t>* skip = nullptr);

// True when `point` is inside the closed mesh (odd number of crossings of a ray from it), the
// triangles in `skip` left out.
bool insideClosedMesh(const Mesh& mesh, const dvec3& point,
                      const std::vector<uint8_t>* skip = nullptr);

}  // namespace penumbra
