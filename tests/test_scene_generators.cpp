#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "scene/edges.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "scene/normals.h"
#include "scene/shapes.h"
#include "scene/teapot.h"

namespace penumbra {
namespace test_scene_generators {

// Sum of |height| over the 25 vertices of makeFractalTerrain(2, 1, 0.5, 1), recorded when the
// generator was written.
constexpr float kFractalLevel2Seed1AbsSum = 1.6264745f;

void expectUnitCornerNormals(const Mesh& mesh) {
  ASSERT_EQ(mesh.corner_normals.size(), mesh.indices.size()) << mesh.name;
  for (const vec3& n : mesh.corner_normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << mesh.name;
}

// Casters must be closed, consistently oriented and facing outwards: shadow volumes of an open
// or inside-out caster count wrongly (z-fail especially).
void expectClosedOutward(Mesh mesh) {
  const EdgeAdjacency adjacency = buildEdges(mesh);
  EXPECT_TRUE(mesh.closed) << mesh.name << ": open " << adjacency.open_edges << ", non-manifold "
                           << adjacency.non_manifold_edges << ", inconsistent "
                           << adjacency.inconsistent_edges;
  EXPECT_GT(signedVolume(mesh), 0.0) << mesh.name << " faces inwards";
  expectUnitCornerNormals(mesh);
}

TEST(SceneGenerators, SolidsAreClosedAndFaceOutwards) {
  expectClosedOutward(makeBox(vec3(-1, 0, -2), vec3(1, 3, 2)));
  expectClosedOutward(makeSphere(vec3(1, 2, 3), 0.5f));
  expectClosedOutward(makeSphere(vec3(0), 1.0f, 3, 2));  // coarsest sphere: two poles, one ring
  expectClosedOutward(makeCylinder(vec3(0, -1, 0), 0.3f, 2.0f));
  expectClosedOutward(makeTorus(vec3(0, 1, 0), 1.0f, 0.2f));
  expectClosedOutward(makeTeapot(vec3(2, 0, 1), 1.5f));
  expectClosedOutward(makeTube({vec3(0), vec3(1, 0.5f, 0), vec3(2, 2, 1)}, {0.3f, 0.2f, 0.1f}, 8, false));
}

// Volumes near the exact ones catch misplaced vertices (a pole in the wrong place, a ring at the
// wrong radius) that closedness alone would not.
TEST(SceneGenerators, VolumesMatchTheShapes) {
  EXPECT_NEAR(signedVolume(makeBox(vec3(-1, 0, -2), vec3(1, 3, 2))), 24.0, 1e-4);
  const double sphere = 4.0 / 3.0 * std::numbers::pi * 8.0;
  EXPECT_NEAR(signedVolume(makeSphere(vec3(1, 2, 3), 2.0f, 64, 32)) / sphere, 1.0, 0.01);
  const double cylinder = std::numbers::pi * 0.09 * 2.0;
  EXPECT_NEAR(signedVolume(makeCylinder(vec3(0, -1, 0), 0.3f, 2.0f, 64)) / cylinder, 1.0, 0.01);
  const double torus = 2.0 * std::numbers::pi * std::numbers::pi * 1.0 * 0.04;
  EXPECT_NEAR(signedVolume(makeTorus(vec3(0), 1.0f, 0.2f, 96, 32)) / torus, 1.0, 0.01);
}

// Flat receivers face +y (the plane) or their given normal (the disk) and are open.
TEST(SceneGenerators, PlaneAndDiskAreOpenAndFaceTheirNormal) {
  Mesh plane = makeGroundPlane(vec3(1, -0.5f, 2), 3.0f);
  EXPECT_EQ(plane.triangleCount(), 2u);
  EXPECT_FALSE((buildEdges(plane), plane.closed));
  for (size_t t = 0; t < plane.triangleCount(); ++t) {
    const vec3 n = glm::cross(plane.vertex(t, 1) - plane.vertex(t, 0), plane.vertex(t, 2) - plane.vertex(t, 0));
    EXPECT_GT(n.y, 0.0f);
  }
  const Bounds3 b = plane.bounds();
  EXPECT_EQ(b.min, vec3(-2, -0.5f, -1));
  EXPECT_EQ(b.max, vec3(4, -0.5f, 5));
  expectUnitCornerNormals(plane);

  const vec3 normal = glm::normalize(vec3(1, 2, -1));
  Mesh disk = makeDisk(vec3(0, 1, 0), normal, 0.5f, 16);
  EXPECT_EQ(disk.triangleCount(), 16u);
  const EdgeAdjacency adjacency = buildEdges(disk);
  EXPECT_EQ(adjacency.open_edges, 16u);
  for (size_t t = 0; t < disk.triangleCount(); ++t) {
    const vec3 n = glm::cross(disk.vertex(t, 1) - disk.vertex(t, 0), disk.vertex(t, 2) - disk.vertex(t, 0));
    EXPECT_GT(glm::dot(n, normal), 0.0f);
  }
}

// The fractal must be reproducible from its seed on every platform: comparisons between
// techniques and against stored results depend on the exact same triangles.
TEST(SceneGenerators, FractalTerrainIsDeterministic) {
  const Mesh a = makeFractalTerrain(6, 4.0f, 0.5f, 42u);
  const Mesh b = makeFractalTerrain(6, 4.0f, 0.5f, 42u);
  const Mesh c = makeFractalTerrain(6, 4.0f, 0.5f, 43u);
  EXPECT_EQ(a.triangleCount(), 2u * 64u * 64u);
  EXPECT_EQ(a.positions.size(), 65u * 65u);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_NE(a.positions, c.positions);
  // Known values: the hash and the height arithmetic (+, *, / only) are exact IEEE operations,
  // so these are the same bits on every platform. A change here changes every fractal scene.
  const Mesh small = makeFractalTerrain(2, 1.0f, 0.5f, 1u);
  ASSERT_EQ(small.positions.size(), 25u);
  float sum = 0.0f;
  for (const vec3& p : small.positions) sum += std::abs(p.y);
  EXPECT_FLOAT_EQ(sum, kFractalLevel2Seed1AbsSum);
  // Every face points up: a heightfield seen from above.
  for (size_t t = 0; t < a.triangleCount(); ++t) {
    const vec3 n = glm::cross(a.vertex(t, 1) - a.vertex(t, 0), a.vertex(t, 2) - a.vertex(t, 0));
    ASSERT_GT(n.y, 0.0f);
  }
  EXPECT_THROW(makeFractalTerrain(0, 1.0f, 0.5f, 1u), Error);
  EXPECT_THROW(makeFractalTerrain(4, 1.0f, 1.5f, 1u), Error);
}

// Crease handling: a cube keeps its faces flat (corners take the face normal) while a sphere's
// corners around one vertex agree (smooth shading).
TEST(SceneGenerators, CornerNormalsFollowCreases) {
  Mesh box = makeBox(vec3(0), vec3(1));
  for (size_t t = 0; t < box.triangleCount(); ++t) {
    const vec3 face = glm::normalize(
        glm::cross(box.vertex(t, 1) - box.vertex(t, 0), box.vertex(t, 2) - box.vertex(t, 0)));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(glm::dot(box.corner_normals[3 * t + k], face), 1.0f, 1e-5f);
  }
  Mesh sphere = makeSphere(vec3(0), 1.0f, 24, 12);
  sphere.corner_normals.clear();
  computeCornerNormals(sphere);
  for (size_t i = 0; i < sphere.indices.size(); ++i) {
    const vec3 radial = glm::normalize(sphere.positions[sphere.indices[i]]);
    EXPECT_GT(glm::dot(sphere.corner_normals[i], radial), 0.99f);
  }
  // A zero-area triangle gets a usable unit normal, not NaN.
  Mesh sliver;
  sliver.positions = {vec3(0), vec3(1, 0, 0), vec3(2, 0, 0)};
  sliver.indices = {0, 1, 2};
  computeCornerNormals(sliver);
  for (const vec3& n : sliver.corner_normals) EXPECT_EQ(n, vec3(0, 1, 0));
}

// Mirroring transforms must keep triangles facing outwards (winding swapped), or a scene file
// with scale [1, -1, 1] would turn every caster inside out.
TEST(SceneGenerators, TransformKeepsOrientation) {
  Mesh box = makeBox(vec3(0), vec3(1, 2, 3));
  transformMesh(box, glm::scale(mat4(1.0f), vec3(1, -1, 1)));
  EXPECT_NEAR(signedVolume(box), 6.0, 1e-5);
  expectClosedOutward(box);
  for (size_t t = 0; t < box.triangleCount(); ++t) {
    const vec3 face = glm::normalize(
        glm::cross(box.vertex(t, 1) - box.vertex(t, 0), box.vertex(t, 2) - box.vertex(t, 0)));
    EXPECT_NEAR(glm::dot(box.corner_normals[3 * t], face), 1.0f, 1e-5f);
  }
  EXPECT_THROW(transformMesh(box, glm::scale(mat4(1.0f), vec3(1, 0, 1))), Error);
}

TEST(SceneGenerators, RejectsBadParameters) {
  EXPECT_THROW(makeBox(vec3(1), vec3(0)), Error);
  EXPECT_THROW(makeSphere(vec3(0), -1.0f), Error);
  EXPECT_THROW(makeCylinder(vec3(0), 1.0f, 0.0f), Error);
  EXPECT_THROW(makeGroundPlane(vec3(0), 0.0f), Error);
  EXPECT_THROW(makeDisk(vec3(0), vec3(0), 1.0f), Error);
  EXPECT_THROW(makeTorus(vec3(0), 0.1f, 0.2f), Error);
}

}  // namespace test_scene_generators
}  // namespace penumbra
