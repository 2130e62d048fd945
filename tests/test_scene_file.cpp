#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_file {

using test::contains;
using test::errorMessage;
using test::ScopedEnv;
using test::ScratchDir;

const char* kValidScene = R"({
  "name": "unit",
  "camera": {"position": [0, 2, 6], "target": [0, 0.5, 0], "fov": 50},
  "lights": [{"center": [1, 5, 2], "radius": 0.3, "color": [1, 0.9, 0.8], "intensity": 0.8}],
  "materials": [{"name": "floor", "albedo": [0.5, 0.5, 0.5]},
                {"name": "red", "albedo": [0.8, 0.1, 0.1], "specular": [0.2, 0.2, 0.2], "shininess": 16}],
  "meshes": [
    {"generator": "plane", "half_size": 5, "material": "floor"},
    {"generator": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "red"},
    {"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": 1,
     "transform": {"translate": [2, 0, 0], "rotate": [0, 90, 0], "scale": 2}}
  ],
  "settings": {"width": 320, "height": 200, "ambient": [0.1, 0.1, 0.1]}
})";

// The documented keys all arrive where they belong; a typo in the reader would silently drop
// a light or a material.
TEST(SceneFile, ReadsEverySection) {
  const Scene scene = parseSceneJson(kValidScene, "unit.json", "");
  EXPECT_EQ(scene.name, "unit");
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(scene.meshes[0].material, 0u);
  EXPECT_EQ(scene.meshes[1].material, 1u);
  EXPECT_EQ(scene.meshes[2].material, 1u);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].radius, 0.3f);
  EXPECT_EQ(scene.lights[0].intensity, 0.8f);
  EXPECT_EQ(scene.materials[1].shininess, 16.0f);
  EXPECT_EQ(scene.settings.width, 320);
  EXPECT_EQ(scene.camera.fov_y, 50.0f);
  EXPECT_EQ(scene.adjacency.size(), 3u);
  // The box is scaled by 2, turned 90 degrees about y (x -> -z), then moved by +2 in x.
  const Bounds3 box = scene.meshes[2].bounds();
  EXPECT_NEAR(box.min.x, 2.0f, 1e-5f);
  EXPECT_NEAR(box.max.x, 4.0f, 1e-5f);
  EXPECT_NEAR(box.min.z, -2.0f, 1e-5f);
  EXPECT_NEAR(box.max.y, 2.0f, 1e-5f);
  EXPECT_TRUE(scene.meshes[2].closed);
}

// "fit" normalises size and stands the mesh on y = 0; a camera is made when none is given.
TEST(SceneFile, FitAndAutomaticCamera) {
  const Scene scene = parseSceneJson(
      R"({"lights": [{"center": [0, 5, 0]}],
          "meshes": [{"generator": "sphere", "center": [10, 10, 10], "radius": 3, "fit": 2}]})",
      "fit.json", "");
  const Bounds3 b = scene.meshes[0].bounds();
  EXPECT_NEAR(b.extent().y, 2.0f, 1e-4f);
  EXPECT_NEAR(b.min.y, 0.0f, 1e-5f);
  EXPECT_NEAR(b.center().x, 0.0f, 1e-5f);
  EXPECT_EQ(scene.name, "fit");
  EXPECT_EQ(scene.materials.size(), 1u);  // the default material
  // The automatic camera looks at the mesh.
  const View view = scene.camera.makeView(scene.settings.width, scene.settings.height);
  const vec4 clip = view.toClip(vec4(b.center(), 1.0f));
  EXPECT_GT(clip.w, 0.0f);
  EXPECT_LT(std::abs(clip.x / clip.w), 0.2f);
  EXPECT_LT(std::abs(clip.y / clip.w), 0.2f);
}

// Mesh files resolve relative to the scene file's folder.
TEST(SceneFile, LoadsRelativeMeshFiles) {
  ScratchDir dir;
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string path = dir.write(
      "scene.json", R"({"lights": [{"center": [0, 5, 5]}], "meshes": [{"file": "tri.obj"}]})");
  const Scene scene = loadSceneFile(path);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "tri.obj");
}

// Each mistake a user can make must give an error naming the file and the key, so a typo in a
// scene file is found in seconds.
TEST(SceneFile, ErrorsNameTheFileAndKey) {
  const auto parse = [](const std::string& text) {
    return errorMessage([&] { parseSceneJson(text, "scene.json", ""); });
  };
  const std::string meshes = R"("meshes": [{"generator": "sphere"}])";
  const std::string light = R"("lights": [{"center": [0, 5, 0]}])";

  std::string message = parse("{\"lights\": [");
  EXPECT_TRUE(contains(message, "scene.json: invalid JSON")) << message;

  message = parse("{" + meshes + ", \"lihgts\": []}");
  EXPECT_TRUE(contains(message, "scene.json: lihgts: unknown key")) << message;

  message = parse(R"({"lights": [{"center": [0, 5, 0]}], "meshes": [{"generator": "box", "min": [0,0,0],
                     "max": [1,1,1], "transform": {"scael": 2}}]})");
  EXPECT_TRUE(contains(message, "scene.json: meshes[0].transform.scael: unknown key")) << message;

  message = parse("{" + meshes + R"(, "lights": [{"center": [0, 5, 0], "radius": "big"}]})");
  EXPECT_EQ(message, "scene.json: lights[0].radius: expected a number");

  message = parse("{" + meshes + R"(, "lights": [{"center": [0, 5, 0], "radius": -1}]})");
  EXPECT_TRUE(contains(message, "scene.json: lights[0].radius: must be >= 0")) << message;

  message = parse("{" + meshes + ", " + light + R"(, "settings": {"width": 0}})");
  EXPECT_TRUE(contains(message, "scene.json: settings.width")) << message;

  message = parse("{" + meshes + ", " + light + R"(, "settings": {"height": 240.5}})");
  EXPECT_TRUE(contains(message, "scene.json: settings.height: expected an integer")) << message;

  message = parse("{" + meshes + R"(, "lights": []})");
  EXPECT_TRUE(contains(message, "scene.json: lights")) << message;

  message = parse("{" + light + R"(, "meshes": [{"generator": "sphere", "material": "gold"}]})");
  EXPECT_TRUE(contains(message, "scene.json: meshes[0].material: no material named 'gold'")) << message;

  message = parse("{" + light + R"(, "meshes": [{"generator": "cube"}]})");
  EXPECT_TRUE(contains(message, "meshes[0].generator: unknown generator 'cube'")) << message;

  message = parse("{" + light + R"(, "meshes": [{"generator": "sphere", "radius": -2}]})");
  EXPECT_TRUE(contains(message, "scene.json: meshes[0]: sphere: radius")) << message;

  message = parse("{" + light + R"(, "meshes": [{"generator": "sphere", "radius": 1, "radius": 2}]})");
  EXPECT_TRUE(contains(message, "scene.json") && contains(message, "'radius' appears twice")) << message;

  message = parse("{" + light + R"(, "meshes": [{"file": "nowhere/absent.obj"}]})");
  EXPECT_TRUE(contains(message, "scene.json: meshes[0].file: nowhere/absent.obj: mesh file not found"))
      << message;

  message = parse("{" + light + R"(, "meshes": []})");
  EXPECT_TRUE(contains(message, "scene.json") && contains(message, "no triangles")) << message;

  message = parse("{" + meshes + ", " + light + R"(, "camera": {"position": [0, 0, 0]}})");
  EXPECT_TRUE(contains(message, "scene.json: camera.target: missing")) << message;

  message = parse("[1, 2]");
  EXPECT_TRUE(contains(message, "scene.json") && contains(message, "JSON object")) << message;

  message = errorMessage([] { loadSceneFile("/nonexistent/scene.json"); });
  EXPECT_TRUE(contains(message, "/nonexistent/scene.json: scene file not found")) << message;
}

// "models:" paths follow PENUMBRA_MODELS; when the model is not there the error says where it
// looked and how to point elsewhere.
TEST(SceneFile, ModelsPrefixUsesTheModelsDirectory) {
  ScratchDir dir;
  dir.write("tiny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const ScopedEnv models("PENUMBRA_MODELS", dir.path());
  const std::string text = R"({"lights": [{"center": [0, 5, 5]}], "meshes": [{"file": "models:tiny.obj"}]})";
  EXPECT_EQ(modelsDirectory(), dir.path());
  EXPECT_EQ(parseSceneJson(text, "m.json", "").meshes[0].triangleCount(), 1u);
  const std::string message = errorMessage([] {
    parseSceneJson(R"({"lights": [{"center": [0, 5, 5]}], "meshes": [{"file": "models:absent.obj"}]})",
                   "m.json", "");
  });
  EXPECT_TRUE(contains(message, "m.json: meshes[0].file") && contains(message, "PENUMBRA_MODELS"))
      << message;
}

}  // namespace test_scene_file
}  // namespace penumbra
