#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/edges.h"
#include "scene/load_mesh.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_load_mesh {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

// A quad written as two OBJ faces loads as 2 triangles over 4 welded vertices, with normals.
TEST(SceneLoadMesh, LoadsAndWeldsAnObj) {
  ScratchDir dir;
  const std::string path = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nf 1 2 3 4\n");
  const Mesh mesh = loadMesh(path);
  EXPECT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.name, "quad.obj");
  ASSERT_EQ(mesh.corner_normals.size(), 6u);
  for (const vec3& n : mesh.corner_normals) EXPECT_NEAR(n.y, 1.0f, 1e-6f);
}

// Normals given in the file are kept (they are the artist's shading), not recomputed.
TEST(SceneLoadMesh, KeepsFileNormals) {
  ScratchDir dir;
  const std::string path = dir.write(
      "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0.6 0 0.8\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n");
  const Mesh mesh = loadMesh(path);
  ASSERT_EQ(mesh.corner_normals.size(), 3u);
  EXPECT_NEAR(mesh.corner_normals[0].x, 0.6f, 1e-6f);
  EXPECT_NEAR(mesh.corner_normals[1].z, 1.0f, 1e-6f);
}

// Each bad input must be an Error naming the file, never a crash or an empty mesh.
TEST(SceneLoadMesh, BadFilesAreClearErrors) {
  ScratchDir dir;
  const std::string missing = dir.path() + "/missing.obj";
  std::string message = errorMessage([&] { loadMesh(missing); });
  EXPECT_TRUE(contains(message, missing) && contains(message, "not found")) << message;

  const std::string garbage = dir.write("garbage.obj", "this is not\na mesh file at all\n");
  message = errorMessage([&] { loadMesh(garbage); });
  EXPECT_TRUE(contains(message, garbage)) << message;

  const std::string bad_index = dir.write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  message = errorMessage([&] { loadMesh(bad_index); });
  EXPECT_TRUE(contains(message, bad_index)) << message;

  const std::string nan = dir.write("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  message = errorMessage([&] { loadMesh(nan); });
  EXPECT_TRUE(contains(message, nan) && contains(message, "non-finite") && contains(message, "vertex 0"))
      << message;

  const std::string empty = dir.write("empty.obj", "");
  message = errorMessage([&] { loadMesh(empty); });
  EXPECT_TRUE(contains(message, empty)) << message;

  const std::string no_faces = dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
  message = errorMessage([&] { loadMesh(no_faces); });
  EXPECT_TRUE(contains(message, no_faces)) << message;

  const std::string only_degenerate = dir.write("degenerate.obj", "v 0 0 0\nv 1 0 0\nf 1 1 2\n");
  message = errorMessage([&] { loadMesh(only_degenerate); });
  EXPECT_TRUE(contains(message, only_degenerate)) << message;
}

// The shared models' edge statistics against the manifest's "welded" analysis. Both weld
// bit-identical positions (numpy's unique also merges -0.0 with +0.0, as we do), so boundary,
// non-manifold and inconsistent counts agree exactly, with one difference: we drop triangles
// that welding made degenerate (a repeated index) before counting edges, while the manifest
// still counts their non-degenerate edges. Only vk-subpass-scene has such triangles (4168); for
// it we assert our counts are no larger (we find 0 open and 939 non-manifold edges where the
// manifest lists 0 and 1455) and that our triangle count is the manifest's minus them.
// If this fails, welding or edge pairing is wrong (or the models changed).
TEST(SceneLoadMesh, SharedModelsMatchTheManifest) {
  const std::filesystem::path dir = modelsDirectory();
  std::ifstream in(dir / "manifest.json");
  if (!in) GTEST_SKIP() << "no shared models at " << dir << " (set PENUMBRA_MODELS)";
  const nlohmann::json manifest = nlohmann::json::parse(in);
  for (const auto& entry : manifest) {
    const std::string file = entry["file"];
    SCOPED_TRACE(file);
    Mesh mesh = loadMesh((dir / file).string());
    const EdgeAdjacency adjacency = buildEdges(mesh);
    const auto& welded = entry["welded"];
    const size_t degenerate = welded["degenerate_tris"];
    EXPECT_EQ(mesh.triangleCount(), size_t(entry["triangles"]) - degenerate);
    if (degenerate == 0) {
      EXPECT_EQ(adjacency.open_edges, size_t(welded["boundary_edges"]));
      EXPECT_EQ(adjacency.non_manifold_edges, size_t(welded["nonmanifold_edges"]));
      EXPECT_EQ(adjacency.inconsistent_edges, size_t(welded["orientation_inconsistent_edges"]));
      EXPECT_EQ(mesh.closed, bool(welded["closed_2manifold"]));
    } else {
      EXPECT_LE(adjacency.open_edges, size_t(welded["boundary_edges"]) + 2 * degenerate);
      EXPECT_LE(adjacency.non_manifold_edges, size_t(welded["nonmanifold_edges"]));
      EXPECT_FALSE(mesh.closed);
    }
  }
}

}  // namespace test_scene_load_mesh
}  // namespace penumbra
