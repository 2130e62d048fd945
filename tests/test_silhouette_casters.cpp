// Caster policies (silhouette.h) on open meshes: the hard shadow volume's two-sided casters and
// the wedges' solid-with-holes casters, whose silhouette must have multiplicity 1 at folds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "open_mesh_util.h"
#include "scene/edges.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {
namespace test_silhouette_casters {

using testing::openSphere;

int maxMultiplicity(const Silhouette& s) {
  int m = 0;
  for (const SilhouetteEdge& e : s.edges) m = std::max(m, std::abs(e.multiplicity));
  return m;
}

// A dome lit from the side and above: its terminator is a fold between light-facing and
// facing-away triangles. Two-sided (the hard volume's policy) gives those edges multiplicity 2,
// which doubles the wedges' penumbra; solid-with-holes must give 1 everywhere, casting the
// light-facing side (the dome covers more of the light's view from outside than from inside).
// If it failed, the open meshes' penumbrae would be black in their inner half again.
TEST(SilhouetteCasters, OpenDomeFoldsHaveMultiplicityOneForWedges) {
  Mesh dome = openSphere(vec3(0.0f), 1.0f, std::numbers::pi / 2);
  const EdgeAdjacency adjacency = buildEdges(dome);
  ASSERT_FALSE(dome.closed);
  ASSERT_EQ(adjacency.inconsistent_edges, 0u);
  const vec3 light(3.0f, 2.0f, 1.0f);
  EXPECT_LT(windingNumber(dome, dvec3(light)), 0.0);
  EXPECT_EQ(maxMultiplicity(findSilhouette(dome, adjacency, light, CasterPolicy::Auto)), 2);
  const Silhouette wedges = findSilhouette(dome, adjacency, light, CasterPolicy::SolidWithHoles);
  EXPECT_EQ(maxMultiplicity(wedges), 1);
  for (size_t t = 0; t < wedges.orientation.size(); ++t) EXPECT_GE(wedges.orientation[t], 0);
}

// A globe with a hole at the bottom and the light inside it: every triangle faces away from the
// light. The light-facing side alone would cast nothing and the globe's shadow would vanish;
// the winding number (about 0.9 here) must select the facing-away side, every triangle.
TEST(SilhouetteCasters, LightInsideOpenGlobeCastsFacingAwaySide) {
  Mesh globe = openSphere(vec3(0.0f), 1.0f, 0.8 * std::numbers::pi);
  const EdgeAdjacency adjacency = buildEdges(globe);
  ASSERT_FALSE(globe.closed);
  const vec3 light(0.0f, 0.1f, 0.0f);
  EXPECT_NEAR(windingNumber(globe, dvec3(light)), 0.9, 0.08);
  const Silhouette s = findSilhouette(globe, adjacency, light, CasterPolicy::SolidWithHoles);
  for (size_t t = 0; t < s.orientation.size(); ++t) EXPECT_EQ(s.orientation[t], -1) << t;
  EXPECT_EQ(maxMultiplicity(s), 1);
  EXPECT_FALSE(s.edges.empty());  // the rim of the hole
}

// The winding number of a closed mesh is its inside indicator (the closed-mesh branch relies on
// insideClosedMesh, which must agree).
TEST(SilhouetteCasters, WindingNumberOfClosedSphere) {
  Mesh sphere = openSphere(vec3(0.0f), 1.0f, std::numbers::pi);
  buildEdges(sphere);
  ASSERT_TRUE(sphere.closed);
  EXPECT_NEAR(windingNumber(sphere, dvec3(0.1, 0.2, -0.3)), 1.0, 1e-9);
  EXPECT_NEAR(windingNumber(sphere, dvec3(2.0, 0.5, 0.0)), 0.0, 1e-9);
  EXPECT_TRUE(insideClosedMesh(sphere, dvec3(0.1, 0.2, -0.3)));
}

// insideClosedMesh answers points outside the mesh's box without a ray, and must still cast one
// for points inside the box: a corner of the box is outside the sphere although inside the box,
// and a point just inside a face of the box but outside the sphere's surface likewise. Failing,
// a light in a caster's box would cast from the wrong facing (findSilhouette).
TEST(SilhouetteCasters, InsideClosedMeshInAndOutOfItsBox) {
  Mesh sphere = openSphere(vec3(0.0f), 1.0f, std::numbers::pi);
  buildEdges(sphere);
  ASSERT_TRUE(sphere.closed);
  const Bounds3 box = sphere.bounds();
  EXPECT_FALSE(insideClosedMesh(sphere, dvec3(3.0, 0.0, 0.0)));   // outside the box
  EXPECT_FALSE(insideClosedMesh(sphere, dvec3(0.0, -1.5, 0.0)));
  EXPECT_FALSE(insideClosedMesh(sphere, dvec3(box.max) * 0.95));   // in the box's corner
  EXPECT_FALSE(insideClosedMesh(sphere, dvec3(box.min) * 0.95));
  EXPECT_FALSE(insideClosedMesh(sphere, dvec3(box.max.x * 0.99, 0.5, 0.0)));  // inside a face
  EXPECT_TRUE(insideClosedMesh(sphere, dvec3(0.0, 0.0, 0.0)));
  EXPECT_TRUE(insideClosedMesh(sphere, dvec3(0.0, 0.9, 0.0)));
}

}  // namespace test_silhouette_casters
}  // namespace penumbra
