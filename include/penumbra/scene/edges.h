#pragma once
// Edge adjacency by pairing directed edges (the approach of Doom 3 BFG's shadow volumes):
// every undirected edge {a, b} lists the triangles that use it and in which direction. A
// triangle traversing a->b with a < b counts +1, b->a counts -1. For a closed, consistently
// oriented manifold every edge has one of each. Open edges (one triangle), edges of three or
// more triangles, and edges two triangles traverse the same way are all kept; the silhouette
// code sums signed contributions so shadow volumes stay balanced for all of them.
#include <cstdint>
#include <vector>

#include <penumbra/scene/mesh.h>

namespace penumbra {

struct EdgeUse {
  uint32_t triangle;
  int8_t sign;  // +1: the triangle traverses v0 -> v1; -1: v1 -> v0
};

struct Edge {
  uint32_t v0, v1;        // v0 < v1 (welded vertex indices)
  uint32_t first_use;     // index into EdgeAdjacency::uses
  uint32_t use_count;
};

// Triangles that repeat another triangle's three vertices in the same winding: a surface stored
// twice (src/scene/repeated_triangles.h says why penumbra wedges leave them out). A face and its
// reverse are not repeats: together they are a two-sided sheet, a closed shell of no volume.
struct RepeatedTriangles {
  // Each triangle whose vertices and winding equal those of a triangle with a smaller index
  // (up to rotation), in increasing order; the first of each set is kept. Degenerate triangles (a
  // repeated index) are never listed: they have no edges.
  std::vector<uint32_t> triangles;
  // The edge diagnostics of the mesh without the listed triangles (EdgeAdjacency's counts
  // include them): whether it is closed, and its edges two triangles traverse the same way.
  bool closed = false;
  size_t inconsistent_edges = 0;
};

struct EdgeAdjacency {
  std::vector<Edge> edges;
  std::vector<EdgeUse> uses;
  // Diagnostics, for scene summaries and tests.
  size_t open_edges = 0;          // used by exactly one triangle
  size_t non_manifold_edges = 0;  // used by three or more triangles
  size_t inconsistent_edges = 0;  // used by two triangles traversing it the same way
  RepeatedTriangles repeated;     // the counts above include these triangles
};

// Builds the adjacency of `mesh` (degenerate triangles, with a repeated index, are skipped) and
// sets mesh.closed (false for a mesh without triangles) and `repeated`. Edges come sorted by
// (v0, v1) and each edge's uses by triangle, so the result is deterministic. Linear time (a
// counting sort by v0). Throws penumbra::Error for an index out of range.
EdgeAdjacency buildEdges(Mesh& mesh);

}  // namespace penumbra
