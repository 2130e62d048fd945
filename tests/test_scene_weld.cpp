#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "scene/weld.h"

namespace penumbra {
namespace test_scene_weld {

// If -0.0 and +0.0 were kept apart, a mesh authored with mirrored halves (x = -0 on one side,
// +0 on the other) would get a crack of open edges along its seam and shadow volumes would leak.
TEST(SceneWeld, MergesPlusAndMinusZero) {
  Mesh mesh;
  mesh.positions = {vec3(0.0f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f),
                    vec3(-0.0f, 1.0f, -0.0f), vec3(1.0f, 0.0f, -0.0f), vec3(1.0f, 1.0f, 0.0f)};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(weldPositions(mesh), 0u);
  EXPECT_EQ(mesh.positions.size(), 4u);
  // The two triangles now share the edge (1,0,0)-(0,1,0) by index.
  EXPECT_EQ(mesh.indices[1], mesh.indices[4]);
  EXPECT_EQ(mesh.indices[2], mesh.indices[3]);
  for (const vec3& p : mesh.positions) {
    for (int axis = 0; axis < 3; ++axis) EXPECT_FALSE(std::signbit(p[axis])) << "a -0.0 survived";
  }
}

// An unindexed quad (as assimp delivers OBJ faces) must share its diagonal after welding, or
// every loaded mesh would look like a soup of open triangles.
TEST(SceneWeld, MergesExactDuplicatesAndKeepsNearOnesApart) {
  Mesh mesh;
  const float nudged = std::nextafter(1.0f, 2.0f);
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0),
                    vec3(0, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0),
                    vec3(nudged, 0, 0), vec3(2, 0, 0), vec3(2, 1, 0)};
  mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  EXPECT_EQ(weldPositions(mesh), 0u);
  // 4 quad corners + 3 for the last triangle: (nudged, 0, 0) is one ulp from (1, 0, 0) and stays
  // separate: welding is exact, never by distance.
  EXPECT_EQ(mesh.positions.size(), 7u);
  EXPECT_EQ(mesh.indices[0], mesh.indices[3]);
  EXPECT_EQ(mesh.indices[2], mesh.indices[4]);
  EXPECT_NE(mesh.indices[6], mesh.indices[1]);
}

// Triangles collapsed by welding must disappear together with their corner normals; a shifted
// normal array would shade every later triangle with its neighbour's normals.
TEST(SceneWeld, DropsDegenerateTrianglesAndKeepsNormalsAligned) {
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0),
                    vec3(5, 5, 5), vec3(5, 5, 5), vec3(6, 5, 5),  // collapses: two equal corners
                    vec3(0, 0, 1), vec3(1, 0, 1), vec3(0, 1, 1)};
  mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  for (int t = 0; t < 3; ++t) {
    for (int k = 0; k < 3; ++k) mesh.corner_normals.push_back(vec3(float(t), float(k), 1.0f));
  }
  EXPECT_EQ(weldPositions(mesh), 1u);
  ASSERT_EQ(mesh.triangleCount(), 2u);
  ASSERT_EQ(mesh.corner_normals.size(), 6u);
  EXPECT_EQ(mesh.corner_normals[0], vec3(0, 0, 1));
  EXPECT_EQ(mesh.corner_normals[3], vec3(2, 0, 1));
  EXPECT_EQ(mesh.corner_normals[5], vec3(2, 2, 1));
  // The collapsed triangle's vertices are no longer referenced and are dropped.
  EXPECT_EQ(mesh.positions.size(), 6u);
  EXPECT_EQ(mesh.vertex(1, 0), vec3(0, 0, 1));
}

// A bad index must be a clear error, not an out-of-bounds read.
TEST(SceneWeld, RejectsOutOfRangeIndices) {
  Mesh mesh;
  mesh.name = "broken";
  mesh.positions = {vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)};
  mesh.indices = {0, 1, 7};
  try {
    weldPositions(mesh);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("broken"), std::string::npos) << e.what();
  }
}

}  // namespace test_scene_weld
}  // namespace penumbra
