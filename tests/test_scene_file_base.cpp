// Scene files over a base scene ("base"): the viewer saves its camera and lights this way, and
// `penumbra render` must read back exactly what was written.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_file_base {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

bool sameBits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }
bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

void expectSameLight(const Light& a, const Light& b) {
  EXPECT_TRUE(sameBits(a.center, b.center));
  EXPECT_TRUE(sameBits(a.radius, b.radius));
  EXPECT_TRUE(sameBits(a.color, b.color));
  EXPECT_TRUE(sameBits(a.intensity, b.intensity));
  EXPECT_EQ(a.shape, b.shape);
  if (a.shape == LightShape::Disk) {
    EXPECT_TRUE(sameBits(a.normal, b.normal));
  }
  if (a.shape == LightShape::Rectangle) {
    EXPECT_TRUE(sameBits(a.edge_u, b.edge_u));
    EXPECT_TRUE(sameBits(a.edge_v, b.edge_v));
  }
  ASSERT_EQ(a.texture == nullptr, b.texture == nullptr);
  if (a.texture) {
    EXPECT_EQ(a.texture->width, b.texture->width);
    ASSERT_EQ(a.texture->texels.size(), b.texture->texels.size());
    for (size_t k = 0; k < a.texture->texels.size(); ++k) {
      EXPECT_TRUE(sameBits(a.texture->texels[k], b.texture->texels[k])) << "texel " << k;
    }
  }
}

// A camera and lights with values no short decimal holds (thirds, tenths) and every light
// shape: if the writer rounded a number or dropped a key, the scene read back would differ,
// and the viewer's saved scene would render another image than the one on screen.
TEST(SceneFileBase, WrittenCameraAndLightsReadBackBitForBit) {
  Scene scene = builtinScene("spheres");
  scene.camera.position = vec3(1.0f / 3.0f, 2.7f, 7.1f);
  scene.camera.target = vec3(0.1f, 0.2f / 3.0f, -0.3f);
  scene.camera.fov_y = 41.3f;
  scene.camera.near_plane = 0.07f;
  scene.lights.clear();
  Light sphere;
  sphere.center = vec3(-1.1f, 6.0f / 7.0f + 4.0f, 2.2f);
  sphere.radius = 0.3f;
  sphere.color = vec3(1.0f, 0.9f, 0.8f);
  sphere.intensity = 0.7f;
  scene.lights.push_back(sphere);
  scene.lights.push_back(diskLight(vec3(0.5f, 5.1f, 0.2f), glm::normalize(vec3(0.1f, -1.0f, 0.2f)), 0.45f));
  Light rectangle = rectangleLight(vec3(0.0f, 5.5f, 1.0f), vec3(0.8f, 0.0f, 0.0f), vec3(0.0f, 0.0f, 0.6f));
  rectangle.texture = makeLightTexture(2, 1, {vec3(1.0f, 0.2f, 0.1f), vec3(0.1f / 3.0f, 0.5f, 1.0f)}, "t");
  scene.lights.push_back(rectangle);
  scene.settings.width = 123;
  scene.settings.height = 77;

  const ScratchDir dir;
  const std::string path = dir.path() + "/saved.json";
  writeSceneOverBase(path, scene, "spheres");
  const Scene read = loadSceneFile(path);

  EXPECT_TRUE(sameBits(read.camera.position, scene.camera.position));
  EXPECT_TRUE(sameBits(read.camera.target, scene.camera.target));
  EXPECT_TRUE(sameBits(read.camera.up, scene.camera.up));
  EXPECT_TRUE(sameBits(read.camera.fov_y, scene.camera.fov_y));
  EXPECT_TRUE(sameBits(read.camera.near_plane, scene.camera.near_plane));
  ASSERT_EQ(read.lights.size(), scene.lights.size());
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    SCOPED_TRACE(i);
    expectSameLight(read.lights[i], scene.lights[i]);
  }
  EXPECT_EQ(read.settings.width, 123);
  EXPECT_EQ(read.settings.height, 77);
  EXPECT_EQ(read.triangleCount(), scene.triangleCount());
  ASSERT_EQ(read.meshes.size(), scene.meshes.size());
  EXPECT_EQ(read.meshes[0].positions, scene.meshes[0].positions);
}

// A base that is a scene file is read relative to the file naming it, and keeps its own lights
// when the file gives none; without that, a saved scene would only work from one folder.
TEST(SceneFileBase, RelativeBaseFileAndKeptLights) {
  const ScratchDir dir;
  dir.write("inner.json", R"({"name": "inner",
    "lights": [{"center": [0, 4, 0], "radius": 0.25}],
    "meshes": [{"generator": "plane", "half_size": 3}, {"generator": "sphere", "center": [0, 1, 0]}]})");
  const std::string outer = dir.write("outer.json", R"({"base": "inner.json",
    "camera": {"position": [0, 3, 5], "target": [0, 0, 0]}})");
  const Scene scene = loadSceneFile(outer);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].radius, 0.25f);
  EXPECT_EQ(scene.camera.position, vec3(0.0f, 3.0f, 5.0f));
  EXPECT_EQ(scene.name, "inner");
}

// Bad bases are named in the error; a file naming itself must fail, not recurse forever.
TEST(SceneFileBase, BadBasesAreRefused) {
  const ScratchDir dir;
  const std::string self = dir.write("self.json", R"({"base": "self.json"})");
  const std::string loop = errorMessage([&] { loadSceneFile(self); });
  EXPECT_TRUE(contains(loop, "nest more than")) << loop;

  const std::string unknown = dir.write("unknown.json", R"({"base": "no-such-scene"})");
  const std::string missing = errorMessage([&] { loadSceneFile(unknown); });
  EXPECT_TRUE(contains(missing, "base")) << missing;
  EXPECT_TRUE(contains(missing, "no-such-scene")) << missing;

  const std::string both = dir.write("both.json",
      R"({"base": "spheres", "meshes": [{"generator": "plane"}]})");
  const std::string mixed = errorMessage([&] { loadSceneFile(both); });
  EXPECT_TRUE(contains(mixed, "meshes")) << mixed;
}

}  // namespace test_scene_file_base
}  // namespace penumbra
