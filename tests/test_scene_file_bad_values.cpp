// Scene files and mesh files with values at the edges of float (issue 10's fuzzing list): a
// correct scene, or a message that names the file and key and says what is wrong.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/load_mesh.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_file_bad_values {

using test::contains;
using test::errorMessage;
using test::ScopedEnv;
using test::ScratchDir;

const char* kLight = R"("lights": [{"center": [0, 5, 0], "radius": 0.2}])";

std::string sceneWithMesh(const std::string& mesh_entry) {
  return std::string(R"({"meshes": [)") + mesh_entry + "], " + kLight + "}";
}

// Generator sizes of 2e9 ran for seconds and ended in std::bad_alloc with no key or file named.
TEST(SceneFileBadValues, GeneratorSizesAreLimitedBeforeAllocating) {
  const auto start = std::chrono::steady_clock::now();
  for (const std::string& entry :
       {std::string(R"({"generator": "sphere", "segments": 2000000000})"),
        std::string(R"({"generator": "sphere", "rings": 2000000000})"),
        std::string(R"({"generator": "cylinder", "segments": 2000000000})"),
        std::string(R"({"generator": "disk", "segments": 2000000000})"),
        std::string(R"({"generator": "torus", "sides": 2000000000})")}) {
    const std::string message =
        errorMessage([&] { parseSceneJson(sceneWithMesh(entry), "big.json", ""); });
    EXPECT_TRUE(contains(message, "big.json: meshes[0]: ")) << message;
    EXPECT_TRUE(contains(message, fmt::format("(the limit is {})", kMaxGeneratedTriangles)))
        << message;
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

// A scale that overflows float: the file and the key are named, not "the transform is
// singular".
TEST(SceneFileBadValues, TransformOverflowNamesFileAndKey) {
  const std::string scale = errorMessage([&] {
    parseSceneJson(sceneWithMesh(R"({"generator": "box", "min": [0, 0, 0], "max": [1e30, 1, 1],
                                     "transform": {"scale": 1e20}})"),
                   "scale.json", "");
  });
  EXPECT_TRUE(contains(scale, "scale.json: meshes[0].transform: ")) << scale;
  EXPECT_TRUE(contains(scale, "out of float range")) << scale;
  EXPECT_FALSE(contains(scale, "singular")) << scale;
}

// "fit" of a box 1e-13 or 1e15 units across: a fine transform whose float determinant
// underflows or overflows was refused as singular. It now fits.
TEST(SceneFileBadValues, FitOfTinyAndHugeMeshesWorks) {
  for (const char* extent : {"1e-13", "1e15", "1e30"}) {
    const Scene scene =
        parseSceneJson(sceneWithMesh(fmt::format(R"({{"generator": "box", "min": [0, 0, 0],
                                       "max": [{0}, {0}, {0}], "fit": 2}})",
                                                 extent)),
                       "fit.json", "");
    const Bounds3 b = scene.meshes[0].bounds();
    EXPECT_NEAR(b.extent().x, 2.0f, 1e-4f) << extent;
    EXPECT_NEAR(b.min.y, 0.0f, 1e-4f) << extent;
  }
}

// A mesh file (not a scene file) 1e-30 to 1e30 units across is framed like the same mesh at
// size 1, with the same normals: the float cross products of a tiny mesh's faces underflowed
// and every corner got the default +y normal (wrong shading, no message).
TEST(SceneFileBadValues, MeshFilesOfExtremeSizeAreFramed) {
  ScratchDir dir;
  auto tetrahedron = [&](const char* size) {
    return loadScene(dir.write(
        fmt::format("tet{}.obj", size),
        fmt::format("v 0 0 0\nv {0} 0 0\nv 0 {0} 0\nv 0 0 {0}\nf 1 3 2\nf 1 2 4\nf 1 4 3\n"
                    "f 2 3 4\n",
                    size)));
  };
  const Scene unit = tetrahedron("1");
  for (const char* size : {"1e-30", "1e-13", "1e15", "1e30"}) {
    const Scene scene = tetrahedron(size);
    EXPECT_NEAR(scene.meshes[0].bounds().extent().y, 2.0f, 1e-4f) << size;
    ASSERT_EQ(scene.meshes[0].corner_normals.size(), unit.meshes[0].corner_normals.size());
    for (size_t i = 0; i < unit.meshes[0].corner_normals.size(); ++i) {
      const vec3 d = scene.meshes[0].corner_normals[i] - unit.meshes[0].corner_normals[i];
      EXPECT_LT(glm::length(d), 1e-5f) << size << " corner " << i;
    }
  }
}

// A unit box scaled by 1e38 is finite but cannot be framed: the message says so, and names
// the key, instead of calling the camera's position not finite.
TEST(SceneFileBadValues, SceneTooLargeToFrameIsNamed) {
  const std::string message = errorMessage([&] {
    parseSceneJson(sceneWithMesh(R"({"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1],
                                     "transform": {"scale": 1e38}})"),
                   "large.json", "");
  });
  EXPECT_TRUE(contains(message, "large.json: camera: not given, and cannot place a camera around "
                                "the scene"))
      << message;
}

// A camera at 1e30 was told its up vector is parallel to the view.
TEST(SceneFileBadValues, FarCameraGetsARangeMessage) {
  const std::string message = errorMessage([&] {
    parseSceneJson(std::string(R"({"meshes": [{"generator": "box", "min": [0,0,0], "max": [1,1,1]}],
                                   "camera": {"position": [1e30, 1, 1], "target": [0, 0, 0]}, )") +
                       kLight + "}",
                   "far.json", "");
  });
  EXPECT_TRUE(contains(message, "far.json: scene 'far': camera position (1e+30, 1, 1)")) << message;
  EXPECT_TRUE(contains(message, "must lie within 1e+18")) << message;
  EXPECT_FALSE(contains(message, "parallel")) << message;
}

// A NUL inside a file name cut every message quoting it at the NUL.
TEST(SceneFileBadValues, NulInAStringIsRefusedWithTheKey) {
  const std::string message = errorMessage(
      [&] { parseSceneJson(sceneWithMesh(R"({"file": "a\u0000b.obj"})"), "nul.json", ""); });
  EXPECT_TRUE(contains(message, "nul.json: meshes[0].file: the string contains a NUL character"))
      << message;
}

// "models:../../x.obj" loaded a file outside the models folder.
TEST(SceneFileBadValues, ModelsPrefixCannotLeaveTheModelsFolder) {
  ScratchDir dir;
  dir.write("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // Restored after the test: later tests in the same process read the models folder.
  const test::ScopedEnv models("PENUMBRA_MODELS", dir.path() + "/models");
  for (const char* file : {"models:../x.obj", "models:sub/../../x.obj", "models:/etc/passwd"}) {
    const std::string message = errorMessage([&] {
      parseSceneJson(sceneWithMesh(fmt::format(R"({{"file": "{}"}})", file)), "escape.json", "");
    });
    EXPECT_TRUE(contains(message, "escape.json: meshes[0].file: ")) << message;
    EXPECT_TRUE(contains(message, "is not a name inside the models folder")) << message;
  }
}

}  // namespace test_scene_file_bad_values
}  // namespace penumbra
