#include <gtest/gtest.h>

#include <cmath>

#include "scene/generators.h"
#include "scene/scene.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_finalize {

using test::contains;
using test::errorMessage;

Scene smallScene() {
  Scene scene;
  scene.name = "small";
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeGroundPlane(vec3(0), 2.0f));
  scene.meshes.push_back(makeBox(vec3(-0.5f, 0, -0.5f), vec3(0.5f, 1, 0.5f)));
  scene.lights.push_back(Light{vec3(0, 5, 0), 0.2f, vec3(1), 1.0f});
  return scene;
}

// Global triangle ids index the eye buffers' primitive ids; a wrong mapping would shade or
// shadow with another mesh's triangle.
TEST(SceneFinalize, TriangleOffsetsAndLocate) {
  Scene scene = smallScene();
  Mesh empty;
  empty.name = "empty";
  scene.meshes.insert(scene.meshes.begin() + 1, empty);  // an empty mesh between the two
  scene.finalize();
  EXPECT_EQ(scene.triangle_offsets, (std::vector<uint32_t>{0, 2, 2, 14}));
  EXPECT_EQ(scene.locateTriangle(0), std::make_pair(0u, 0u));
  EXPECT_EQ(scene.locateTriangle(1), std::make_pair(0u, 1u));
  EXPECT_EQ(scene.locateTriangle(2), std::make_pair(2u, 0u));
  EXPECT_EQ(scene.locateTriangle(13), std::make_pair(2u, 11u));
  ASSERT_EQ(scene.adjacency.size(), 3u);
  EXPECT_TRUE(scene.meshes[2].closed);
  EXPECT_FALSE(scene.meshes[0].closed);
  EXPECT_EQ(scene.adjacency[0].open_edges, 4u);
  // Finalizing again rebuilds instead of appending.
  scene.finalize();
  EXPECT_EQ(scene.triangle_offsets.size(), 4u);
  EXPECT_EQ(scene.adjacency.size(), 3u);
}

// Meshes built in code without shading normals get computed ones rather than failing later.
TEST(SceneFinalize, FillsMissingCornerNormals) {
  Scene scene = smallScene();
  scene.meshes[1].corner_normals.clear();
  scene.finalize();
  EXPECT_EQ(scene.meshes[1].corner_normals.size(), scene.meshes[1].indices.size());
}

// Every unrenderable scene must be refused with a message naming the scene and the problem.
TEST(SceneFinalize, RejectsUnrenderableScenes) {
  const auto failure = [](auto change) {
    Scene scene = smallScene();
    change(scene);
    return errorMessage([&] { scene.finalize(); });
  };
  std::string message = failure([](Scene& s) { s.lights.clear(); });
  EXPECT_TRUE(contains(message, "scene 'small'") && contains(message, "no lights")) << message;
  message = failure([](Scene& s) { s.lights[0].radius = -1.0f; });
  EXPECT_TRUE(contains(message, "light 0") && contains(message, "radius")) << message;
  message = failure([](Scene& s) { s.lights[0].radius = NAN; });
  EXPECT_TRUE(contains(message, "radius")) << message;
  message = failure([](Scene& s) { s.lights[0].intensity = -0.5f; });
  EXPECT_TRUE(contains(message, "intensity")) << message;
  message = failure([](Scene& s) { s.meshes[1].material = 3; });
  EXPECT_TRUE(contains(message, "material index 3")) << message;
  message = failure([](Scene& s) { s.meshes[1].positions[2].y = INFINITY; });
  EXPECT_TRUE(contains(message, "mesh 1") && contains(message, "vertex 2")) << message;
  message = failure([](Scene& s) { s.meshes.clear(); });
  EXPECT_TRUE(contains(message, "no triangles")) << message;
  message = failure([](Scene& s) { s.materials.clear(); });
  EXPECT_TRUE(contains(message, "no materials")) << message;
  message = failure([](Scene& s) { s.settings.width = 0; });
  EXPECT_TRUE(contains(message, "image size")) << message;
  message = failure([](Scene& s) { s.camera.target = s.camera.position; });
  EXPECT_TRUE(contains(message, "camera")) << message;
  message = failure([](Scene& s) { s.meshes[1].indices[0] = 100; });
  EXPECT_TRUE(contains(message, "references vertex 100")) << message;
}

}  // namespace test_scene_finalize
}  // namespace penumbra
