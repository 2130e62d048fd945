// Instances in scene files ("prototypes", "instances"): a mesh read once and placed many times,
// its copies the same triangles as the prototype moved by each transform, and the whole scene
// written back (writeSceneFile) reads as it was.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/mesh_ops.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_instances {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

bool sameBits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

// Two prototypes, three instances: one moved and turned, one mirrored by a matrix, one with
// its material overridden; and a plain mesh, which stays first.
const char* kInstancedScene = R"({
  "materials": [{"name": "floor"}, {"name": "stone", "albedo": [0.5, 0.5, 0.5]}, {"name": "red"}],
  "meshes": [{"generator": "plane", "half_size": 20, "material": "floor"}],
  "prototypes": [
    {"name": "tower", "generator": "box", "min": [-1, 0, -1], "max": [1, 5, 1], "material": "stone"},
    {"name": "ball", "generator": "sphere", "center": [0, 1, 0], "radius": 1, "segments": 8, "rings": 6}
  ],
  "instances": [
    {"prototype": "tower", "transform": {"translate": [4, 0, 0], "rotate": [0, 30, 0]}},
    {"prototype": 1, "matrix": [[-1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, -3]]},
    {"prototype": "tower", "transform": {"translate": [-4, 0, 0], "scale": 0.5}, "material": "red", "name": "small tower"}
  ],
  "lights": [{"center": [0, 10, 0], "radius": 0.5}]
})";

Scene parse(const std::string& text) { return parseSceneJson(text, "city.json", ""); }

// If the copies were not the prototype's triangles moved by each instance's transform, the
// techniques would draw something other than the file describes.
TEST(SceneInstances, CopiesAreThePrototypeMovedByEachTransform) {
  const Scene scene = parse(kInstancedScene);
  ASSERT_EQ(scene.prototypes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 3u);
  ASSERT_EQ(scene.instance_meshes, 3u);
  ASSERT_EQ(scene.meshes.size(), 4u);
  EXPECT_EQ(scene.meshes[0].name, "plane");
  const Mesh& tower = *scene.prototypes[0];
  const Mesh& copy = scene.meshes[1];
  ASSERT_EQ(copy.indices, tower.indices);
  const mat4 expected = glm::translate(mat4(1.0f), vec3(4, 0, 0)) *
                        glm::rotate(mat4(1.0f), glm::radians(30.0f), vec3(0, 1, 0));
  for (size_t v = 0; v < tower.positions.size(); ++v) {
    const vec3 p = vec3(expected * vec4(tower.positions[v], 1.0f));
    EXPECT_NEAR(glm::length(copy.positions[v] - p), 0.0f, 1e-5f) << "vertex " << v;
  }
  EXPECT_EQ(copy.material, 1u);             // the prototype's material
  EXPECT_EQ(scene.meshes[3].material, 2u);  // overridden
  EXPECT_EQ(scene.meshes[3].name, "small tower");
  EXPECT_EQ(scene.meshes[1].name, "tower #0");
  EXPECT_EQ(scene.triangleCount(),
            2 + 2 * tower.triangleCount() + scene.prototypes[1]->triangleCount());
  EXPECT_EQ(scene.adjacency.size(), scene.meshes.size());
}

// A mirroring matrix must re-wind the copy: its fronts would face inwards and shadow volumes
// would count the wrong way.
TEST(SceneInstances, MirroredCopyStaysOutwardFacing) {
  const Scene scene = parse(kInstancedScene);
  EXPECT_GT(signedVolume(scene.meshes[2]), 0.0);
  EXPECT_TRUE(scene.meshes[2].closed);
  // The unit ball around x = 0, mirrored about x = 1: it spans x from 1 to 3.
  EXPECT_NEAR(scene.meshes[2].bounds().min.x, 1.0f, 1e-5f);
  EXPECT_NEAR(scene.meshes[2].bounds().max.x, 3.0f, 1e-5f);
}

// The prototypes are held once: copying the scene (every FrameRenderer takes one) must not
// copy them, and a second finalize() must not add the copies twice.
TEST(SceneInstances, PrototypesAreSharedAndFinalizeDoesNotDuplicate) {
  Scene scene = parse(kInstancedScene);
  const Scene copy = scene;
  EXPECT_EQ(copy.prototypes[0].get(), scene.prototypes[0].get());
  const size_t meshes = scene.meshes.size();
  scene.finalize();
  EXPECT_EQ(scene.meshes.size(), meshes);
  scene.instances.push_back(scene.instances[0]);
  scene.finalize();
  EXPECT_EQ(scene.meshes.size(), meshes + 1);
  EXPECT_EQ(scene.triangle_offsets.size(), scene.meshes.size() + 1);
}

std::string withInstances(const std::string& instances, const std::string& extra = "") {
  return std::string(
             R"({"prototypes": [{"name": "tower", "generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]},
                                       {"name": "ball", "generator": "sphere"}],)") +
         extra + R"("instances": )" + instances + R"(, "lights": [{"center": [0, 9, 0]}]})";
}

// A file that places a large mesh many times would have every technique's world-space copies
// run the machine out of memory; it is refused before any copy, naming the file and the count.
TEST(SceneInstances, TooManyFlattenedTrianglesAreRefusedBeforeCopying) {
  // A sphere of 512 x 512 quads (about half a million triangles) placed 300 times.
  std::string instances;
  for (int i = 0; i < 300; ++i)
    instances += fmt::format(R"({}{{"prototype": 0, "transform": {{"translate": [{}, 0, 0]}}}})",
                             i == 0 ? "" : ", ", 3 * i);
  const std::string text = fmt::format(R"({{
  "prototypes": [{{"generator": "sphere", "radius": 1, "segments": 512, "rings": 512}}],
  "instances": [{}],
  "lights": [{{"center": [0, 10, 0], "radius": 0.5}}]
}})", instances);
  const std::string message = errorMessage([&] { (void)parse(text); });
  EXPECT_TRUE(contains(message, "city.json: instances: ")) << message;
  EXPECT_TRUE(contains(message, "300 instances hold")) << message;
  EXPECT_TRUE(contains(message, "more than the 134217728 a scene can render")) << message;
}

// Each bad entry names the file, the key path and the problem, so a typo in a file of
// thousands of instances is found at once.
TEST(SceneInstances, BadEntriesNameTheFileKeyAndProblem) {
  const auto message = [](const std::string& text) {
    return errorMessage([&] { (void)parse(text); });
  };
  EXPECT_TRUE(contains(
      message(withInstances(R"([{"prototype": "towr"}])")),
      "city.json: instances[0].prototype: no prototype named 'towr' (prototypes: tower, ball)"));
  EXPECT_TRUE(contains(
      message(withInstances(R"([{"prototype": 0}, {"prototype": 2}])")),
      "instances[1].prototype: prototype index 2 is out of range (there are 2 prototypes)"));
  EXPECT_TRUE(
      contains(message(withInstances(R"([{"prototype": 0, "transform": {}, "matrix": []}])")),
               "instances[0]: takes \"transform\" or \"matrix\", not both"));
  EXPECT_TRUE(
      contains(message(withInstances(
                   R"([{"prototype": 0, "matrix": [[1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}])")),
               "instances[0].matrix[0]: expected 3 rows of 4 numbers"));
  EXPECT_TRUE(
      contains(message(withInstances(
                   R"([{"prototype": 0, "matrix": [[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0]]}])")),
               "instances[0].matrix: is singular"));
  EXPECT_TRUE(contains(message(withInstances(R"([{"prototype": 0, "material": "gold"}])")),
                       "instances[0].material: no material named 'gold'"));
  EXPECT_TRUE(contains(message(withInstances(R"([{"prototype": 0, "scale": 2}])")),
                       "instances[0].scale: unknown key"));
  EXPECT_TRUE(contains(
      message(withInstances(
          R"([{"prototype": 0, "transform": {"translate": [3e38, 0, 0], "scale": 3e38}}])")),
      "city.json: instances: instance 0 ('tower #0')"));
  EXPECT_TRUE(
      contains(message(R"({"instances": [{"prototype": 0}], "lights": [{"center": [0, 9, 0]}]})"),
               "instances[0].prototype: names a prototype, but the scene has no \"prototypes\""));
  EXPECT_TRUE(
      contains(message(R"({"meshes": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}],
                                   "prototypes": [{"generator": "sphere"}], "lights": [{"center": [0, 9, 0]}]})"),
               "prototypes: are given but no \"instances\" place them"));
  EXPECT_TRUE(contains(message(R"({"prototypes": [{"generator": "sphere"}, {"generator": "sphere"}],
                                   "instances": [{"prototype": 0}], "lights": [{"center": [0, 9, 0]}]})"),
                       "prototypes[1]: prototype 'sphere' is defined twice"));
  EXPECT_TRUE(contains(message(R"({"base": "spheres", "instances": []})"),
                       "instances: a scene with a \"base\" takes its meshes"));
  EXPECT_TRUE(contains(message(withInstances("[]")), "has no triangles"));
}

// The whole scene written and read back: every position, triangle, instance matrix and
// material the same bits. If the writer flattened the instances, or rounded a matrix entry,
// the file would grow with the city or render another image.
TEST(SceneInstances, WrittenSceneReadsBackBitForBit) {
  ScratchDir dir;
  const Scene scene = parse(kInstancedScene);
  const std::string path = dir.path() + "/written.json";
  writeSceneFile(path, scene);
  const Scene back = loadSceneFile(path);
  ASSERT_EQ(back.prototypes.size(), scene.prototypes.size());
  ASSERT_EQ(back.instances.size(), scene.instances.size());
  ASSERT_EQ(back.meshes.size(), scene.meshes.size());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    EXPECT_EQ(
        std::memcmp(&back.instances[i].transform, &scene.instances[i].transform, sizeof(mat4)), 0)
        << "instance " << i;
    EXPECT_EQ(back.instances[i].material, scene.instances[i].material);
    EXPECT_EQ(back.instances[i].prototype, scene.instances[i].prototype);
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    SCOPED_TRACE(scene.meshes[m].name);
    EXPECT_EQ(back.meshes[m].indices, scene.meshes[m].indices);
    ASSERT_EQ(back.meshes[m].positions.size(), scene.meshes[m].positions.size());
    for (size_t v = 0; v < scene.meshes[m].positions.size(); ++v) {
      EXPECT_TRUE(sameBits(back.meshes[m].positions[v], scene.meshes[m].positions[v])) << v;
    }
    EXPECT_EQ(back.meshes[m].material, scene.meshes[m].material);
  }
  EXPECT_TRUE(sameBits(back.camera.position, scene.camera.position));
  ASSERT_EQ(back.materials.size(), scene.materials.size());
  EXPECT_EQ(back.materials[1].name, "stone");
}

}  // namespace test_scene_instances
}  // namespace penumbra
