#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_builtin {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

bool isFlatReceiver(const Mesh& mesh) { return mesh.name == "plane" || mesh.name == "fractal"; }

// Every built-in scene must be renderable as it comes: finalized, lit by a spherical light (soft
// shadows need a radius), every caster closed (shadow volumes rely on it), and the camera
// looking at the scene.
TEST(SceneBuiltin, EverySceneIsRenderable) {
  const std::vector<std::string> names = builtinSceneNames();
  EXPECT_EQ(names, (std::vector<std::string>{"spheres", "columns", "fractal", "year2002", "multilight"}));
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(isBuiltinScene(name));
    const Scene scene = builtinScene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_GT(scene.triangleCount(), 0u);
    ASSERT_EQ(scene.triangle_offsets.size(), scene.meshes.size() + 1);
    EXPECT_EQ(scene.triangle_offsets.back(), scene.triangleCount());
    EXPECT_EQ(scene.adjacency.size(), scene.meshes.size());
    ASSERT_FALSE(scene.lights.empty());
    for (const Light& light : scene.lights) {
      EXPECT_GT(light.radius, 0.0f);
      EXPECT_GT(light.center.y, 1.0f);  // above the floor
    }
    for (const Mesh& mesh : scene.meshes) {
      if (!isFlatReceiver(mesh)) {
        EXPECT_TRUE(mesh.closed) << mesh.name;
      }
      EXPECT_EQ(mesh.corner_normals.size(), mesh.indices.size()) << mesh.name;
    }
    const View view = scene.camera.makeView(scene.settings.width, scene.settings.height);
    const vec4 clip = view.toClip(vec4(scene.camera.target, 1.0f));
    EXPECT_GT(clip.w, 0.0f);
  }
}

// The fractal scene is the papers' complex receiver: about 100k triangles.
TEST(SceneBuiltin, FractalHasAboutHundredThousandTriangles) {
  const Scene scene = builtinScene("fractal");
  EXPECT_GE(scene.triangleCount(), 90000u);
  EXPECT_LE(scene.triangleCount(), 140000u);
}

// Three lights of different colours, so per-light visibility is visible in the picture.
TEST(SceneBuiltin, MultilightHasThreeColouredLights) {
  const Scene scene = builtinScene("multilight");
  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_NE(scene.lights[0].color, scene.lights[1].color);
  EXPECT_NE(scene.lights[1].color, scene.lights[2].color);
  EXPECT_NE(scene.lights[0].color, scene.lights[2].color);
}

// Unknown names must list what exists, so a user can correct a typo.
TEST(SceneBuiltin, UnknownNamesListTheBuiltins) {
  std::string message = errorMessage([] { builtinScene("sphere"); });
  EXPECT_TRUE(contains(message, "sphere") && contains(message, "spheres, columns")) << message;
  message = errorMessage([] { loadScene("colums"); });
  EXPECT_TRUE(contains(message, "colums") && contains(message, "year2002")) << message;
  EXPECT_FALSE(isBuiltinScene("colums"));
}

// A bare mesh becomes a scene: normalised to ~2 units standing on the floor at y = 0, lit and
// framed. Checked with a small file so it runs without the shared models.
TEST(SceneBuiltin, SceneForMeshStandsTheMeshOnTheFloor) {
  ScratchDir dir;
  const std::string path = dir.write(
      "tetra.obj", "v 10 10 10\nv 30 10 10\nv 10 50 10\nv 10 10 30\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  for (const Scene& scene : {sceneForMesh(path), loadScene(path)}) {
    ASSERT_EQ(scene.meshes.size(), 2u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_TRUE(mesh.closed);
    const Bounds3 b = mesh.bounds();
    EXPECT_NEAR(b.min.y, 0.0f, 1e-5f);
    EXPECT_NEAR(b.extent().y, 2.0f, 1e-4f);  // the largest extent, proportions kept
    EXPECT_NEAR(b.extent().x, 1.0f, 1e-4f);
    const Bounds3 floor = scene.meshes[1].bounds();
    EXPECT_LE(floor.max.y, 0.0f);
    EXPECT_GT(floor.extent().x, 8.0f);
    EXPECT_GT(scene.lights[0].center.y, b.max.y);
    EXPECT_EQ(scene.name, "tetra");
  }
}

// Every scene file in scenes/ and tests/data/scenes/ must load (those whose models are absent
// are skipped, visibly): a broken scene file would only be noticed by a user.
TEST(SceneBuiltin, EverySceneFileLoads) {
  const std::filesystem::path root(PENUMBRA_SOURCE_DIR);
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& folder : {root / "scenes", root / "tests" / "data" / "scenes"}) {
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), 13u);
  std::vector<std::string> skipped;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    std::ifstream in(file);
    const nlohmann::json json = nlohmann::json::parse(in);
    bool models_present = true;
    for (const auto& mesh : json["meshes"]) {
      if (!mesh.contains("file")) continue;
      const std::string name = mesh["file"];
      if (name.starts_with("models:") && !std::filesystem::exists(modelPath(name.substr(7)))) {
        models_present = false;
      }
    }
    if (!models_present) {
      skipped.push_back(file.filename().string());
      continue;
    }
    const Scene scene = loadSceneFile(file.string());
    EXPECT_GT(scene.triangleCount(), 0u);
    EXPECT_FALSE(scene.lights.empty());
    // The light must not sit inside any closed mesh, or the whole scene would be in shadow.
    for (const Light& light : scene.lights) {
      for (const Mesh& mesh : scene.meshes) {
        const Bounds3 b = mesh.bounds();
        const bool inside_box = glm::all(glm::greaterThan(light.center, b.min)) &&
                                glm::all(glm::lessThan(light.center, b.max));
        if (mesh.closed) {
          EXPECT_FALSE(inside_box) << mesh.name;
        }
      }
    }
  }
  if (!skipped.empty()) {
    GTEST_SKIP() << skipped.size() << " scene files skipped, their models are not in "
                 << modelsDirectory() << " (set PENUMBRA_MODELS)";
  }
}

}  // namespace test_scene_builtin
}  // namespace penumbra
