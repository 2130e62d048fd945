#pragma once
// Internal to the wedge builder: the silhouette split into unit edges, and how they join at
// silhouette vertices (2002 paper, section 4.1, Figure 5; section 8 for junctions).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/mesh.h"
#include "shadows/stages/silhouettes/silhouette.h"
#include "shadows/wedge/wedge.h"

namespace penumbra::wedge_detail {

// One unit of silhouette multiplicity, oriented a -> b so that the hard quad (b, a, a', b')
// faces out of the shadow: a = v0, b = v1 for multiplicity > 0, the reverse for < 0, exactly as
// the side quads of shadows/stages/silhouettes/silhouette.h are (v1, v0, v0', v1') with weight m.
struct UnitEdge {
  uint32_t va = 0, vb = 0;
  uint32_t silhouette_edge = 0;  // index into Silhouette::edges
  dvec3 a{0.0}, b{0.0};
  // Nearly parallel to the light direction at a or at b (section 8): no usable quad normal.
  bool parallel = false;
  dvec3 n{0.0};  // unit quad normal out of the shadow; zero when parallel
  dvec3 t{0.0};  // unit a -> b (zero for a zero-length edge)
};

// Splits the silhouette into unit edges (the |m| copies of an edge are consecutive) and flags
// the nearly parallel ones: those whose line is within `parallel_sin` (the sine of the
// threshold angle) of the direction from the light centre `c` at either end.
std::vector<UnitEdge> makeUnitEdges(const Mesh& mesh, const Silhouette& silhouette, const dvec3& c,
                                    double parallel_sin);

// Unit edge `in` (.. -> vertex) continues as unit edge `out` (vertex -> ..).
struct VertexPairing {
  uint32_t in = 0, out = 0, vertex = 0;
};

struct Pairings {
  std::vector<VertexPairing> pairings;
  // Per unit edge, the pairing at its a end (where it is `out`) and at its b end (where it is
  // `in`), or kNoWedgeLink.
  std::vector<uint32_t> at_a, at_b;
  size_t junction_vertices = 0;
};

// Pairs incoming and outgoing unit edges at every silhouette vertex. The silhouette is a
// 1-cycle, so each vertex has as many of one as of the other. With one of each they pair; at a
// junction (more than two distinct silhouette edges, which the paper leaves open, section 8)
// each incoming edge, in index order, takes the outgoing one with the smallest signed turning
// angle about the light direction (ties by index): the sharpest turn toward the shadow side,
// which keeps shadows that only touch at the vertex (a bow-tie) as separate loops instead of
// merging them through a reflex corner. Deterministic.
Pairings pairAtVertices(const std::vector<UnitEdge>& edges, const dvec3& c);

}  // namespace penumbra::wedge_detail
