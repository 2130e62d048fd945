// Penumbra wedges on valid but unusual input: meshes whose every triangle is stored twice, a
// sheet edge-on to the light's centre, lights as large as their distance to the casters. Each
// must give the right image (against the undoubled mesh or the ray-traced oracle) or a precise
// error; tiny images keep the whole file fast.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/generators.h"
#include "scene/repeated_triangles.h"
#include "scene/scene_file.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"
#include "eye_frame_util.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_wedge_unusual_input {

const char* const kWedgeTechniques[] = {"wedge-2002", "wedge-3pass", "wedge-1pass"};

Mesh quadMesh(const std::string& name, std::vector<vec3> corners) {
  Mesh m;
  m.name = name;
  m.positions = std::move(corners);
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A horizontal square at height 1, wound to face up (toward the lights above it).
Mesh floatingQuad() {
  return quadMesh("quad", {vec3(-0.5f, 1.0f, -0.5f), vec3(-0.5f, 1.0f, 0.5f),
                           vec3(0.5f, 1.0f, 0.5f), vec3(0.5f, 1.0f, -0.5f)});
}

// The mesh with every triangle stored a second time (reversed: wound the other way, which makes
// each face a two-sided sheet).
Mesh doubled(Mesh m, bool reversed = false) {
  m.corner_normals.clear();  // recomputed by finalize for the doubled triangles
  const size_t n = m.indices.size();
  for (size_t i = 0; i < n; i += 3) {
    m.indices.push_back(m.indices[i]);
    m.indices.push_back(m.indices[i + (reversed ? 2 : 1)]);
    m.indices.push_back(m.indices[i + (reversed ? 1 : 2)]);
  }
  return m;
}

// A floor under one caster, seen from above and in front, lit by one spherical light.
Scene sceneWith(Mesh caster, vec3 light_center, float radius) {
  Scene s;
  s.name = "unusual";
  s.meshes.push_back(makeGroundPlane(vec3(0.0f), 4.0f));
  s.meshes.push_back(std::move(caster));
  Light light;
  light.center = light_center;
  light.radius = radius;
  s.lights.push_back(light);
  s.camera.position = vec3(0.0f, 4.0f, 4.0f);
  s.camera.target = vec3(0.0f, 0.5f, 0.0f);
  s.settings.width = 64;
  s.settings.height = 48;
  s.materials.push_back(Material{});
  s.finalize();
  return s;
}

Image<float> visibility(const std::string& technique, const Scene& scene, int rays = 0) {
  const testing::EyeFrame f = testing::makeEyeFrame(scene, 64, 48);
  TechniqueConfig config(technique);
  if (rays > 0) {
    config.options<ReferenceOptions>().rays = rays;
    config.options<ReferenceOptions>().seed = 1;
  }
  return renderShadows(config, f.scene, f.scene.lights.at(0), f.view, f.eye).visibility;
}

double maxDifference(const Image<float>& a, const Image<float>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(double(a[i]) - b[i]));
  return worst;
}

// The repeats are found, and without them a box stored twice is closed again; if not, the
// wedges would cast the doubled box with multiplicity 2. A face stored with both windings is a
// two-sided sheet, not a repeat: if it were, scanned meshes' two-sided patches would open.
TEST(WedgeUnusualInput, RepeatedTrianglesAreFoundAndTheMeshWithoutThemJudged) {
  Mesh box = doubled(makeBox(vec3(-0.5f, 0.5f, -0.5f), vec3(0.5f, 1.5f, 0.5f)));
  const EdgeAdjacency adjacency = buildEdges(box);
  const size_t n = box.triangleCount() / 2;
  ASSERT_EQ(adjacency.repeated.triangles.size(), n);
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(adjacency.repeated.triangles[i], n + i);
  EXPECT_FALSE(box.closed);  // the edge counts still describe the file as it is
  EXPECT_TRUE(adjacency.repeated.closed);
  EXPECT_EQ(adjacency.repeated.inconsistent_edges, 0u);

  Mesh sheet = doubled(floatingQuad(), true);
  const EdgeAdjacency two_sided = buildEdges(sheet);
  EXPECT_TRUE(two_sided.repeated.triangles.empty());
  EXPECT_EQ(two_sided.repeated.closed, sheet.closed);

  Mesh single = makeBox(vec3(0.0f), vec3(1.0f));
  const EdgeAdjacency plain = buildEdges(single);
  EXPECT_TRUE(plain.repeated.triangles.empty());
  EXPECT_TRUE(plain.repeated.closed);
}

// One face repeated many times takes the hashed path (more than a few uses per edge): all but
// the first copy are repeats. If this failed, a file of a million coincident faces would keep
// its multiplicity.
TEST(WedgeUnusualInput, AFaceRepeatedManyTimesKeepsOneCopy) {
  Mesh m = quadMesh("fan", {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
  m.indices = {};
  for (int i = 0; i < 40; ++i) m.indices.insert(m.indices.end(), {0u, 1u, 2u});
  m.indices.insert(m.indices.end(), {0u, 2u, 1u});  // the reverse: kept
  m.indices.insert(m.indices.end(), {0u, 2u, 3u});
  const EdgeAdjacency adjacency = buildEdges(m);
  ASSERT_EQ(adjacency.repeated.triangles.size(), 39u);
  EXPECT_EQ(adjacency.repeated.triangles.front(), 1u);
  EXPECT_EQ(adjacency.repeated.triangles.back(), 39u);
}

// Every triangle stored twice (a quad, a closed box): the wedges
// must render exactly the single mesh's visibility. Before the fix every silhouette edge had
// multiplicity 2, two coincident wedges each subtracted the covered light, and the penumbra
// was darkened twice around the whole outline (max difference 0.5).
TEST(WedgeUnusualInput, EveryTriangleDoubledRendersAsTheSingleMesh) {
  const Mesh casters[] = {floatingQuad(),
                          makeBox(vec3(-0.5f, 0.5f, -0.5f), vec3(0.5f, 1.5f, 0.5f))};
  for (const Mesh& caster : casters) {
    const Scene single = sceneWith(caster, vec3(0.3f, 3.0f, 0.2f), 0.4f);
    const Scene twice = sceneWith(doubled(caster), vec3(0.3f, 3.0f, 0.2f), 0.4f);
    for (const char* technique : kWedgeTechniques) {
      EXPECT_EQ(maxDifference(visibility(technique, twice), visibility(technique, single)), 0.0)
          << technique << " on " << caster.name << " doubled";
    }
  }
}

}  // namespace test_wedge_unusual_input
}  // namespace penumbra

namespace penumbra {
namespace test_wedge_unusual_input {

// A light whose radius reaches a silhouette edge has no wedge planes there (they must touch the
// sphere from outside, 2002 paper, section 4.1): every wedge technique refuses the frame and
// says which light, mesh and edge, and the largest radius that works. Before, the quad's
// shadow came out as a dark star with streaks (radius 2 at distance 1.51) and, at radius 100,
// as half-black floors.
TEST(WedgeUnusualInput, LightReachingASilhouetteEdgeIsRefusedByName) {
  // The quad's nearest silhouette edge, x = 0.5 at height 1, is sqrt(1.5^2 + 0.2^2) = 1.513
  // from the light centre.
  const vec3 centre(0.3f, 2.5f, 0.2f);
  for (const float radius : {2.0f, 1.52f, 100.0f, 1e38f}) {
    const Scene scene = sceneWith(floatingQuad(), centre, radius);
    for (const char* technique : kWedgeTechniques) {
      const std::string message = test::errorMessage([&] { (void)visibility(technique, scene); });
      EXPECT_TRUE(test::contains(message, "with radius ")) << message;
      EXPECT_TRUE(test::contains(message, "reaches silhouette edge")) << message;
      EXPECT_TRUE(test::contains(message, "of mesh 'quad', 1.51327 from its centre")) << message;
      EXPECT_TRUE(test::contains(message, "use a radius below 1.51327")) << message;
    }
  }
  // Just inside the limit the wedges build and render (the approximation is then coarse, but
  // the construction holds).
  const Scene fits = sceneWith(floatingQuad(), centre, 1.5f);
  for (const char* technique : kWedgeTechniques) EXPECT_NO_THROW((void)visibility(technique, fits));
}

// The scene reader refuses radii no technique can use (beyond 1000 times the scene's size) with
// the file and key; a large radius on a far light (a sun) and one merely larger than the
// distance to the casters are read (the wedges then decide, above).
TEST(WedgeUnusualInput, SceneReaderRefusesAbsurdLightRadii) {
  const auto parse = [](const std::string& center, const std::string& radius) {
    return parseSceneJson(R"({"meshes": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}],
                              "lights": [{"center": )" +
                              center + R"(, "radius": )" + radius + "}]}",
                          "scene.json", ".");
  };
  std::string message = test::errorMessage([&] { (void)parse("[0, 5, 0]", "1e38"); });
  EXPECT_TRUE(test::contains(message,
                             "scene.json: lights[0].radius: 1e+38 is larger than the "
                             "scene by orders of magnitude"))
      << message;
  EXPECT_TRUE(test::contains(message, "at most 5196.15")) << message;  // 1000 * |(1, 5, 1)|
  message = test::errorMessage([&] { (void)parse("[0, 5, 0]", "1e300"); });
  EXPECT_TRUE(test::contains(message, "scene.json: lights[0].radius:")) << message;
  EXPECT_EQ(parse("[0, 5, 0]", "100").lights.at(0).radius, 100.0f);
  EXPECT_EQ(parse("[0, 1e6, 0]", "5000").lights.at(0).radius, 5000.0f);
}

}  // namespace test_wedge_unusual_input
}  // namespace penumbra
