#include "scene/repeated_triangles.h"

#include <unordered_map>

namespace penumbra {

namespace {

// The vertex of triangle t that is not on edge {v0, v1}.
uint32_t opposite(const Mesh& mesh, uint32_t t, const Edge& e) {
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = mesh.indices[3 * size_t(t) + k];
    if (v != e.v0 && v != e.v1) return v;
  }
  return e.v0;  // unreachable for the non-degenerate triangles the adjacency holds
}

}  // namespace

RepeatedTriangles findRepeatedTriangles(const Mesh& mesh, const EdgeAdjacency& adjacency) {
  RepeatedTriangles out;
  std::vector<uint8_t> repeated(mesh.triangleCount(), 0);
  bool any = false;
  // Two triangles with the same vertices and winding traverse each shared edge the same way and
  // have the same vertex opposite it. An edge's uses come in triangle order (edges.h), so the
  // first use with a given opposite vertex and direction is the triangle that is kept.
  constexpr uint32_t kPairwiseLimit = 8;
  // Key: the opposite vertex times two, plus one for a use against the edge's direction.
  std::unordered_map<uint64_t, uint32_t> first_with;
  for (const Edge& e : adjacency.edges) {
    if (e.use_count < 2) continue;
    const EdgeUse* uses = &adjacency.uses[e.first_use];
    if (e.use_count <= kPairwiseLimit) {
      for (uint32_t j = 1; j < e.use_count; ++j) {
        const uint32_t oj = opposite(mesh, uses[j].triangle, e);
        for (uint32_t i = 0; i < j; ++i) {
          if (uses[i].sign == uses[j].sign && opposite(mesh, uses[i].triangle, e) == oj) {
            repeated[uses[j].triangle] = 1;
            any = true;
            break;
          }
        }
      }
    } else {
      // Many triangles on one edge (a fan, or a file that repeats one face a million times):
      // hashing keeps this linear.
      first_with.clear();
      for (uint32_t j = 0; j < e.use_count; ++j) {
        const uint64_t key =
            2 * uint64_t(opposite(mesh, uses[j].triangle, e)) + (uses[j].sign < 0 ? 1 : 0);
        if (!first_with.emplace(key, uses[j].triangle).second) {
          repeated[uses[j].triangle] = 1;
          any = true;
        }
      }
    }
  }
  if (!any) {
    out.closed = mesh.closed;
    out.inconsistent_edges = adjacency.inconsistent_edges;
    return out;
  }
  for (size_t t = 0; t < repeated.size(); ++t)
    if (repeated[t]) out.triangles.push_back(uint32_t(t));
  // The same classification as buildEdges (edges.cpp), over the kept uses only.
  size_t open = 0, non_manifold = 0, edges = 0;
  for (const Edge& e : adjacency.edges) {
    uint32_t count = 0;
    int sign_sum = 0;
    for (uint32_t u = e.first_use; u < e.first_use + e.use_count; ++u) {
      if (repeated[adjacency.uses[u].triangle]) continue;
      ++count;
      sign_sum += adjacency.uses[u].sign;
    }
    if (count == 0) continue;
    ++edges;
    if (count == 1) {
      ++open;
    } else if (count >= 3) {
      ++non_manifold;
    } else if (sign_sum != 0) {
      ++out.inconsistent_edges;
    }
  }
  out.closed = edges > 0 && open == 0 && non_manifold == 0 && out.inconsistent_edges == 0;
  return out;
}

}  // namespace penumbra
