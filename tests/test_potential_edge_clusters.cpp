// potentialEdges skips a cluster of edges whose triangles the light sees all from the front or
// all from the back (potential_edges.h: PlaneCluster, clusterSide) without visiting its edges,
// and a cluster of triangles so without evaluating their planes. The skip must change nothing:
// an edge skipped that is a potential silhouette would be missing from every pixel's sums (a
// penumbra drawn as lit or as umbra where the oracle sees part of the light), and a triangle
// given the wrong side or a wrong "cuts the light" would change the signs or the cutting list.
// Compared here with the same scene's geometry with the cluster lists emptied (every edge and
// triangle visited), field for field, for lights far away, near and inside the meshes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/stages/potential_edges/potential_edges.h"

namespace penumbra {
namespace test_potential_edge_clusters {

void expectSameEdges(const PotentialEdges& got, const PotentialEdges& want,
                     const std::string& where) {
  ASSERT_EQ(got.edges.size(), want.edges.size()) << where;
  for (size_t i = 0; i < got.edges.size(); ++i) {
    const PotentialEdge &g = got.edges[i], &w = want.edges[i];
    ASSERT_TRUE(g.a == w.a && g.b == w.b && g.first_triangle == w.first_triangle &&
                g.triangle_count == w.triangle_count && g.scene_edge == w.scene_edge &&
                g.centre_normal == w.centre_normal)
        << where << ": edge " << i;
  }
  ASSERT_EQ(got.triangles.size(), want.triangles.size()) << where;
  for (size_t i = 0; i < got.triangles.size(); ++i) {
    const EdgeTriangle &g = got.triangles[i], &w = want.triangles[i];
    ASSERT_TRUE(g.id == w.id && g.light_above == w.light_above && g.cuts == w.cuts &&
                g.winding == w.winding && g.opposite == w.opposite && g.normal == w.normal &&
                g.offset == w.offset)
        << where << ": edge triangle " << i;
  }
  ASSERT_EQ(got.cutting.size(), want.cutting.size()) << where;
  for (size_t i = 0; i < got.cutting.size(); ++i)
    ASSERT_EQ(got.cutting[i].id, want.cutting[i].id) << where << ": cutting triangle " << i;
  EXPECT_EQ(got.scene_edges, want.scene_edges) << where;
}

// Lights around a scene: its own (given a radius where it has none), one far above, one just
// off the bounding sphere, one at the centre (inside or between the meshes), and a large one.
std::vector<Light> lightsAround(const Scene& scene) {
  std::vector<Light> lights;
  const Bounds3 bounds = scene.bounds();
  const vec3 centre = bounds.center();
  const float radius = bounds.radius();
  for (Light light : scene.lights) {
    if (!(light.radius > 0.0f)) light.radius = 0.05f * radius;
    lights.push_back(light);
  }
  Light light;
  light.center = centre + vec3(0.3f, 20.0f, 0.2f) * radius;
  light.radius = 0.5f * radius;
  lights.push_back(light);
  light.center = centre + vec3(0.6f, 0.8f, 0.0f) * (1.05f * radius);
  light.radius = 0.02f * radius;
  lights.push_back(light);
  light.center = centre;
  light.radius = 0.1f * radius;
  lights.push_back(light);
  light.center = centre + vec3(0.0f, 3.0f, 1.0f) * radius;
  light.radius = 1.5f * radius;
  lights.push_back(light);
  return lights;
}

// If this failed, a cluster skipped by its bounds would hold a potential silhouette edge or a
// triangle cutting the light, or give a triangle the wrong side of the light centre.
TEST(PotentialEdgeClusters, SkippingClustersChangesNoEdge) {
  for (const std::string& name : builtinSceneNames()) {
    const Scene scene = builtinScene(name);
    const EdgeGeometry clustered = edgeGeometry(scene);
    EdgeGeometry visited = clustered;
    visited.edge_clusters.clear();
    visited.triangle_clusters.clear();
    const std::vector<Light> lights = lightsAround(scene);
    for (size_t l = 0; l < lights.size(); ++l) {
      const std::string where = name + " light " + std::to_string(l);
      const PotentialEdges got = potentialEdges(scene, clustered, lights[l]);
      const PotentialEdges want = potentialEdges(scene, visited, lights[l]);
      expectSameEdges(got, want, where);
      EXPECT_EQ(want.skipped_edges, 0u) << where;
    }
  }
}

// A finely tessellated globe under a far light: most of its clusters face the light or face
// away wholly. If this failed, the clusters would skip nothing (their bounds too loose, or
// never usable) and every edge of a dense mesh would be visited per light again; the result
// is still compared with visiting every edge.
TEST(PotentialEdgeClusters, DenseGlobeSkipsMostEdges) {
  Scene scene;
  scene.name = "dense-globe";
  const uint32_t material = addMaterial(scene, "grey", vec3(0.7f));
  addMesh(scene, makeSphere(vec3(0.0f, 1.0f, 0.0f), 1.0f, 256, 128), material);
  addLight(scene, vec3(2.0f, 9.0f, 1.0f), 0.5f);
  scene.finalize();
  const EdgeGeometry clustered = edgeGeometry(scene);
  EdgeGeometry visited = clustered;
  visited.edge_clusters.clear();
  visited.triangle_clusters.clear();
  const PotentialEdges got = potentialEdges(scene, clustered, scene.lights[0]);
  expectSameEdges(got, potentialEdges(scene, visited, scene.lights[0]), "dense globe");
  EXPECT_GT(got.skipped_edges, got.scene_edges / 2);
  EXPECT_LT(got.edges.size(), got.scene_edges - got.skipped_edges);
}

}  // namespace test_potential_edge_clusters
}  // namespace penumbra
