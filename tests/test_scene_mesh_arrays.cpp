// Meshes given as arrays in memory (scene/mesh_arrays.h) and the scene files' {"arrays": i}
// entries: the Python module's numpy meshes go through these, so they must get the loader's
// checks and welding.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "scene/mesh_arrays.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_mesh_arrays {

using test::contains;
using test::errorMessage;

// Two triangles of a unit square sharing the edge 0-2, with vertex 4 a copy of vertex 2.
MeshArrays square() {
  MeshArrays arrays;
  arrays.vertices = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 1};
  arrays.triangles = {0, 2, 1, 0, 3, 4};
  return arrays;
}

// Welded as a file's mesh: without it the two triangles would not share their edge and the
// shadow techniques would see an open crack.
TEST(MeshArrays, AreWeldedWithNormals) {
  const Mesh mesh = meshFromArrays(square(), "square");
  EXPECT_EQ(mesh.name, "square");
  EXPECT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.corner_normals.size(), 6u);
  EXPECT_EQ(mesh.file_counts.vertices, 5u);
  EXPECT_EQ(mesh.file_counts.triangles, 2u);
}

// Each bad array is refused with a message naming the mesh and the problem, never a crash or a
// mesh with garbage in it.
TEST(MeshArrays, BadArraysAreRefusedByName) {
  MeshArrays arrays = square();
  arrays.vertices.push_back(1.0f);
  std::string message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "m: the vertices hold 16 numbers, not 3")) << message;

  arrays = square();
  arrays.triangles.pop_back();
  message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "m: the triangles hold 5 indices, not 3")) << message;

  arrays = square();
  arrays.vertices[4] = std::numeric_limits<float>::quiet_NaN();
  message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "m: vertex 1 has a non-finite coordinate")) << message;

  arrays = square();
  arrays.triangles[5] = 5;
  message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "triangle 1 (corner 2) uses vertex 5, out of range: there are 5"))
      << message;

  arrays = square();
  arrays.triangles[0] = -1;
  message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "uses vertex -1, out of range")) << message;

  arrays = square();
  arrays.triangles = {0, 2, 4, 1, 1, 1};  // 2 and 4 weld: both triangles collapse
  message = errorMessage([&] { meshFromArrays(arrays, "m"); });
  EXPECT_TRUE(contains(message, "m: every triangle is degenerate")) << message;

  message = errorMessage([&] { meshFromArrays(MeshArrays{}, "m"); });
  EXPECT_TRUE(contains(message, "m: the mesh has no vertices")) << message;
}

const char* kArraysScene = R"({
  "lights": [{"center": [0, 5, 0], "radius": 0.2}],
  "meshes": [{"generator": "plane"},
             {"arrays": 0, "name": "quad", "transform": {"translate": [0, 1, 0]}}]})";

// An {"arrays": i} entry takes the i-th mesh given, with the keys a file entry has.
TEST(MeshArrays, SceneEntriesTakeTheGivenArrays) {
  const Scene scene = parseSceneJson(kArraysScene, "py.json", "", {square()});
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[1].name, "quad");
  EXPECT_EQ(scene.meshes[1].triangleCount(), 2u);
  EXPECT_EQ(scene.meshes[1].bounds().min.y, 1.0f);
}

// Scene files cannot name arrays, an index must exist, and the array checks name the entry.
TEST(MeshArrays, SceneEntryErrorsNameTheKey) {
  std::string message = errorMessage([&] { parseSceneJson(kArraysScene, "s.json", ""); });
  EXPECT_TRUE(contains(message, "s.json: meshes[1].arrays: names in-memory mesh arrays")) << message;

  MeshArrays bad = square();
  bad.triangles[1] = 9;
  message = errorMessage([&] { parseSceneJson(kArraysScene, "s.json", "", {bad}); });
  EXPECT_TRUE(contains(message, "s.json: meshes[1]: quad: triangle 0 (corner 1) uses vertex 9"))
      << message;

  const std::string two = R"({"lights": [{"center": [0, 5, 0]}], "meshes": [{"arrays": 1}]})";
  message = errorMessage([&] { parseSceneJson(two, "s.json", "", {square()}); });
  EXPECT_TRUE(contains(message, "s.json: meshes[0].arrays: 1 is out of range: 1 mesh arrays"))
      << message;
}

}  // namespace test_scene_mesh_arrays
}  // namespace penumbra
