#include <gtest/gtest.h>

#include "scene/edges.h"
#include "scene/generators.h"

namespace penumbra {
namespace test_scene_edges {

Mesh meshOf(std::vector<vec3> positions, std::vector<uint32_t> indices) {
  Mesh mesh;
  mesh.name = "test";
  mesh.positions = std::move(positions);
  mesh.indices = std::move(indices);
  return mesh;
}

// Every use's sign must say how its triangle traverses the edge: the silhouette code sums these
// signs, and a wrong one unbalances the shadow-volume counts.
void expectSignsMatchTriangles(const Mesh& mesh, const EdgeAdjacency& adjacency) {
  for (const Edge& edge : adjacency.edges) {
    ASSERT_LT(edge.v0, edge.v1);
    for (uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
      const EdgeUse& use = adjacency.uses[u];
      int found = 0;
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = mesh.indices[3 * use.triangle + k];
        const uint32_t b = mesh.indices[3 * use.triangle + (k + 1) % 3];
        if (a == edge.v0 && b == edge.v1) found = 1;
        if (a == edge.v1 && b == edge.v0) found = -1;
      }
      EXPECT_EQ(found, use.sign) << "edge " << edge.v0 << "-" << edge.v1;
    }
  }
}

// A closed tetrahedron: 6 edges, each used once in each direction; anything else means the
// pairing is broken and closed meshes would be treated as open.
TEST(SceneEdges, TetrahedronIsClosed) {
  Mesh mesh = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)},
                     {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_EQ(adjacency.edges.size(), 6u);
  EXPECT_EQ(adjacency.uses.size(), 12u);
  EXPECT_EQ(adjacency.open_edges, 0u);
  EXPECT_EQ(adjacency.non_manifold_edges, 0u);
  EXPECT_EQ(adjacency.inconsistent_edges, 0u);
  EXPECT_TRUE(mesh.closed);
  for (const Edge& edge : adjacency.edges) {
    ASSERT_EQ(edge.use_count, 2u);
    EXPECT_EQ(adjacency.uses[edge.first_use].sign + adjacency.uses[edge.first_use + 1].sign, 0);
  }
  expectSignsMatchTriangles(mesh, adjacency);
}

// An open quad: the shared diagonal plus 4 boundary edges.
TEST(SceneEdges, OpenQuadHasFourOpenEdges) {
  Mesh mesh = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)},
                     {0, 1, 2, 0, 2, 3});
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_EQ(adjacency.edges.size(), 5u);
  EXPECT_EQ(adjacency.open_edges, 4u);
  EXPECT_FALSE(mesh.closed);
  expectSignsMatchTriangles(mesh, adjacency);
}

// Three fins on one edge: a non-manifold edge that must keep all three uses.
TEST(SceneEdges, ThreeTrianglesOnOneEdgeAreNonManifold) {
  Mesh mesh = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1)},
                     {0, 1, 2, 1, 0, 3, 0, 1, 4});
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_EQ(adjacency.non_manifold_edges, 1u);
  EXPECT_EQ(adjacency.open_edges, 6u);
  EXPECT_FALSE(mesh.closed);
  bool found = false;
  for (const Edge& edge : adjacency.edges) {
    if (edge.v0 == 0 && edge.v1 == 1) {
      found = true;
      EXPECT_EQ(edge.use_count, 3u);
    }
  }
  EXPECT_TRUE(found);
  expectSignsMatchTriangles(mesh, adjacency);
}

// Two triangles traversing their shared edge the same way (one flipped): counted as
// inconsistent, and the mesh is not closed even if every edge has two uses.
TEST(SceneEdges, SameDirectionUsesAreInconsistent) {
  Mesh mesh = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0)},
                     {0, 1, 2, 0, 1, 3});
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_EQ(adjacency.inconsistent_edges, 1u);
  EXPECT_FALSE(mesh.closed);
  // A tetrahedron with one face flipped: all edges have 2 uses, 3 of them inconsistent.
  Mesh flipped = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)},
                        {0, 1, 2, 0, 1, 3, 0, 3, 2, 1, 2, 3});
  const EdgeAdjacency flipped_adjacency = buildEdges(flipped);
  EXPECT_EQ(flipped_adjacency.open_edges, 0u);
  EXPECT_EQ(flipped_adjacency.inconsistent_edges, 3u);
  EXPECT_FALSE(flipped.closed);
}

// Triangles with a repeated index have no area and no real edges; counting them would add
// bogus open edges.
TEST(SceneEdges, DegenerateTrianglesAreSkipped) {
  Mesh mesh = meshOf({vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)},
                     {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 1, 1, 2});
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_EQ(adjacency.edges.size(), 6u);
  EXPECT_EQ(adjacency.uses.size(), 12u);
  EXPECT_TRUE(mesh.closed);
}

// A grid's boundary is 4 * cells-per-side open edges, everything inside is manifold; the edge
// list covers every triangle edge exactly once.
TEST(SceneEdges, TerrainGridCounts) {
  Mesh terrain = makeFractalTerrain(5, 1.0f, 0.5f, 7u);
  const EdgeAdjacency adjacency = buildEdges(terrain);
  EXPECT_EQ(adjacency.open_edges, 4u * 32u);
  EXPECT_EQ(adjacency.non_manifold_edges, 0u);
  EXPECT_EQ(adjacency.inconsistent_edges, 0u);
  EXPECT_EQ(adjacency.uses.size(), 3 * terrain.triangleCount());
  // Euler for a disk: V - E + F = 1.
  EXPECT_EQ(int64_t(terrain.positions.size()) - int64_t(adjacency.edges.size()) +
                int64_t(terrain.triangleCount()),
            1);
  expectSignsMatchTriangles(terrain, adjacency);
}

}  // namespace test_scene_edges
}  // namespace penumbra
