// Up axes of mesh files (scene/up_axis.h): `--up` and "up" in a scene file's mesh entries.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "scene/up_axis.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_up_axis {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

// The axis named up becomes +y, by a rotation (determinant +1, so windings stay
// counter-clockwise). If this failed, z-up scans would lie on their side or turn inside out.
TEST(UpAxis, TurnsTheNamedAxisUpWithoutMirroring) {
  EXPECT_EQ(vec3(upAxisToY(UpAxis::Z) * vec4(0, 0, 1, 0)), vec3(0, 1, 0));
  EXPECT_EQ(vec3(upAxisToY(UpAxis::Z) * vec4(1, 0, 0, 0)), vec3(1, 0, 0));
  EXPECT_EQ(vec3(upAxisToY(UpAxis::X) * vec4(1, 0, 0, 0)), vec3(0, 1, 0));
  EXPECT_EQ(vec3(upAxisToY(UpAxis::X) * vec4(0, 0, 1, 0)), vec3(0, 0, 1));
  EXPECT_EQ(upAxisToY(UpAxis::Y), mat4(1.0f));
  for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    EXPECT_FLOAT_EQ(glm::determinant(mat3(upAxisToY(up))), 1.0f);
  }
  EXPECT_EQ(parseUpAxis("z"), UpAxis::Z);
  EXPECT_TRUE(contains(errorMessage([] { parseUpAxis("-z"); }), "'-z' must be x, y or z"));
}

// A z-up column (tall along z) stands up, in a scene file ("up": "z") and as a mesh file given
// to loadScene. If this failed, "up" would be ignored or applied after "fit" (a wrong size).
TEST(UpAxis, SceneFileAndMeshFileStandZUpMeshesUp) {
  ScratchDir dir;
  dir.write("column.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 4\nf 1 2 3\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::string scene = dir.write(
      "s.json", R"({"lights": [{"center": [0, 9, 9]}],
                    "meshes": [{"file": "column.obj", "up": "z", "fit": 2}]})");
  const Bounds3 b = loadSceneFile(scene).meshes[0].bounds();
  EXPECT_FLOAT_EQ(b.extent().y, 2.0f);  // the 4-unit z extent, fitted to 2, now along y
  EXPECT_FLOAT_EQ(b.extent().z, 0.5f);

  const Scene from_mesh = loadScene(dir.path() + "/column.obj", UpAxis::Z);
  const Bounds3 m = from_mesh.meshes[0].bounds();
  EXPECT_GT(m.extent().y, 3.0f * m.extent().z);

  const std::string bad = dir.write(
      "bad.json", R"({"lights": [{"center": [0, 9, 9]}],
                      "meshes": [{"file": "column.obj", "up": "w"}]})");
  const std::string message = errorMessage([&] { loadSceneFile(bad); });
  EXPECT_TRUE(contains(message, "bad.json: meshes[0].up") && contains(message, "x, y or z"))
      << message;
  // A scene file or built-in scene has its own axes: a global --up would be an error, not
  // silently ignored.
  EXPECT_TRUE(contains(errorMessage([&] { loadScene(scene, UpAxis::Z); }),
                       "applies to a mesh file"));
}

}  // namespace test_scene_up_axis
}  // namespace penumbra
