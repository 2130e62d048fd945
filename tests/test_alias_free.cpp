// The alias-free shadow map (`alias-free`) against ground truth: the one-ray oracle on every
// built-in scene and shared model scene (the bar: at most 0.01 % of covered pixels
// differ, all on shadow boundaries), a square over a plane whose shadow edge is computed
// analytically, the occluder test's tie rule on a shared edge, and its work counters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "eye_frame_util.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/scene_file.h"
#include "shadow_test_util.h"
#include "shadows/aliasfree/alias_free_technique.h"
#include "shadows/aliasfree/light_grids.h"
#include "shadows/aliasfree/occluder_test.h"
#include "shadows/stages/light_sampling/ray_origin.h"

namespace penumbra {
namespace test_alias_free {

using testing::compareHardWithOracle;
using testing::sphereOverGround;

// The same bars as the hard shadow volumes (tests/test_volume_oracle.cpp): 0.01 % of covered
// pixels, with a floor of 10 pixels for small images, and 0.03 % on the open, dense meshes of
// ../shared/models.
constexpr double kMaxDifferingFraction = 1e-4;
constexpr double kMaxDifferingFractionModels = 3e-4;

void expectMatchesOracle(const testing::OracleComparison& c, const std::string& what,
                         double max_fraction = kMaxDifferingFraction) {
  EXPECT_GT(c.agreement.covered, 0u) << what;
  EXPECT_EQ(c.agreement.off_boundary, 0u) << what << ": differing pixels away from any boundary";
  const double allowed = std::max(max_fraction * double(c.agreement.covered), 10.0);
  EXPECT_LE(double(c.agreement.differing), allowed)
      << what << ": " << c.agreement.differing << " of " << c.agreement.covered << " differ";
  std::printf("%s: %llu of %llu covered pixels differ (%.4f %%), %llu off any boundary\n",
              what.c_str(), (unsigned long long)c.agreement.differing,
              (unsigned long long)c.agreement.covered, 100.0 * c.agreement.differingFraction(),
              (unsigned long long)c.agreement.off_boundary);
}

TechniqueConfig aliasFree(int tile_samples = AliasFreeOptions{}.tile_samples) {
  return TechniqueConfig("alias-free", AliasFreeOptions{tile_samples});
}

// If this failed, a built-in scene would have shadow pixels the ray tracer disagrees with away
// from any shadow edge: a missed or wrongly binned occluder, or a wrong side of a plane.
TEST(AliasFreeOracle, BuiltinScenes) {
  for (const std::string& name : builtinSceneNames()) {
    const Scene scene = builtinScene(name);
    const View view = scene.camera.makeView(320, 214);
    for (size_t l = 0; l < scene.lights.size(); ++l) {
      const auto c = compareHardWithOracle(scene, view, aliasFree(), l);
      expectMatchesOracle(c, name + " light " + std::to_string(l));
    }
  }
}

// Every mesh of ../shared/models in its scene file, the open and non-manifold ones included.
TEST(AliasFreeOracle, SharedModelScenes) {
  if (!std::filesystem::exists(std::filesystem::path(modelsDirectory()) / "bunny-lowres.obj"))
    GTEST_SKIP() << "shared models not found in " << modelsDirectory();
  const auto [scenes, skipped] = testing::forEachSceneFileWithModels(
      [](const std::filesystem::path& path, const Scene& scene) {
        const View view = scene.camera.makeView(320, 214);
        for (size_t l = 0; l < scene.lights.size(); ++l) {
          const auto c = compareHardWithOracle(scene, view, aliasFree(), l);
          expectMatchesOracle(c, path.filename().string(), kMaxDifferingFractionModels);
        }
      });
  EXPECT_GT(scenes, 0) << skipped << " skipped";
}

// Directions from the light to every covered pixel's depth-buffer point: close enough to the
// samples to tell which light grids a frame gets.
LightGrids gridsOf(const testing::OracleComparison& c, const View& view, const vec3& light) {
  std::vector<dvec3> d;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x)
      if (c.eye.depth.depth.at(x, y) > 0.0f)
        d.push_back(view.unproject(x, y, c.eye.depth.depth.at(x, y)) - dvec3(light));
  return LightGrids(d, 16);
}

// A light just above the ground among the visible geometry: the samples surround it, no single
// frustum holds them, so they go to the six cube faces. If this failed, occluders would be lost
// at the faces' seams. And a light high above: one frustum.
TEST(AliasFreeOracle, LightAmongTheSamplesUsesCubeFaces) {
  const vec3 low(2.5f, 2.2f, 0.3f);  // beside the sphere: it casts a long shadow on the ground
  const Scene scene = sphereOverGround(vec3(6, 4, 6), vec3(0, 1, 0), low);
  const View view = scene.camera.makeView(200, 134);
  const auto c = compareHardWithOracle(scene, view, aliasFree());
  expectMatchesOracle(c, "light among the samples");
  EXPECT_FALSE(gridsOf(c, view, low).singleFrustum());
  int shadowed = 0;
  for (size_t i = 0; i < c.technique.visibility.size(); ++i)
    shadowed += c.eye.depth.depth[i] > 0 && c.technique.visibility[i] == 0.0f;
  EXPECT_GT(shadowed, 1000) << "the test needs shadows across the cube faces, has " << shadowed;

  const vec3 high(0, 12, 0);
  const Scene under = sphereOverGround(vec3(0.2f, 0.6f, 0.1f), vec3(4, 0, 3), high);
  const View under_view = under.camera.makeView(200, 134);
  const auto u = compareHardWithOracle(under, under_view, aliasFree());
  expectMatchesOracle(u, "eye in shadow, light high above");
  EXPECT_TRUE(gridsOf(u, under_view, high).singleFrustum());
}

// A light inside a closed sphere: every outside point is in shadow, but for a tie or two on the
// sphere's outline, where the eye pass's depth can put the shaded point a hair inside the
// tessellated sphere (the oracle then sees the light too). If the count grew, a closed mesh
// would be letting light through.
TEST(AliasFreeOracle, LightInsideClosedMesh) {
  const Scene scene = sphereOverGround(vec3(5, 4, 6), vec3(0, 1, 0), vec3(0, 2, 0));
  const auto c = compareHardWithOracle(scene, scene.camera.makeView(160, 107), aliasFree());
  expectMatchesOracle(c, "light inside");
  int lit = 0;
  for (size_t i = 0; i < c.technique.visibility.size(); ++i)
    lit += c.eye.depth.depth[i] > 0 && c.technique.visibility[i] != 0.0f;
  EXPECT_LE(lit, 3);
}

// Bad input is refused by name, and awkward but valid lights get the oracle's answer: a light
// lying exactly in the ground's plane (every ground triangle edge-on to it: they cast nothing,
// and the ground neither faces it nor away), and one exactly at a vertex of the sphere.
TEST(AliasFreeInput, NonFiniteLightRefusedAndDegenerateLightsMatchTheOracle) {
  Scene scene = sphereOverGround(vec3(5, 4, 6), vec3(0, 1, 0), vec3(3, 0, 1));
  const View view = scene.camera.makeView(160, 107);
  expectMatchesOracle(compareHardWithOracle(scene, view, aliasFree()), "light in the ground plane");
  // On the sphere's surface the light puts the sphere's whole shadow edge on its tangent plane
  // there, and the triangles around the vertex pass through the light (they cast nothing here;
  // the oracle's rays, shortened by 1e-6 before the light, decide them their own way): pixels
  // along that edge are ties, so only differences off a boundary are errors.
  const vec3 vertex = scene.meshes[1].positions[scene.meshes[1].positions.size() / 2];
  scene.lights[0].center = vertex;
  const auto at_vertex = compareHardWithOracle(scene, view, aliasFree());
  EXPECT_EQ(at_vertex.agreement.off_boundary, 0u) << "light at a vertex";
  EXPECT_LE(at_vertex.agreement.differing, at_vertex.agreement.covered / 100)
      << "light at a vertex";

  const testing::EyeFrame f = testing::makeEyeFrame(scene, 40, 27);
  Light bad = f.scene.lights[0];
  bad.center.x = std::numeric_limits<float>::quiet_NaN();
  try {
    renderShadows(aliasFree(), f.scene, bad, f.view, f.eye);
    ADD_FAILURE() << "a NaN light centre must be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("light centre is not finite"), std::string::npos)
        << e.what();
  }
}

// A 2 x 2 square at height 1 over a ground plane, a point light above: a ground point is in
// shadow exactly when the segment from it to the light crosses y = 1 inside the square. The
// technique must agree on every ground pixel whose crossing is farther than 1e-6 from the
// square's outline (closer is a tie of rounding), which puts its shadow edge exactly where the
// geometry does: no bias moves it, no texel grid jags it. The square's two triangles share a
// diagonal that crosses the shadow: a crack in the tie rule would show as lit pixels along it.
TEST(AliasFreeAnalytic, SquareOverPlaneShadowEdge) {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeGroundPlane(vec3(0), 10.0f));
  Mesh square;
  square.name = "square";
  square.positions = {vec3(-1, 1, -1), vec3(1, 1, -1), vec3(1, 1, 1), vec3(-1, 1, 1)};
  square.indices = {0, 2, 1, 0, 3, 2};
  square.corner_normals.assign(square.indices.size(), vec3(0, 1, 0));
  scene.meshes.push_back(square);
  const vec3 light(0.3f, 4.0f, 0.2f);
  scene.lights.push_back(Light{light, 0.0f, vec3(1), 1.0f});
  scene.camera.position = vec3(2.5f, 5.0f, 4.0f);
  scene.camera.target = vec3(0, 0, 0);
  scene.finalize();
  const testing::EyeFrame f = testing::makeEyeFrame(scene, 160, 107);
  const TechniqueResult r = renderShadows(aliasFree(), f.scene, f.scene.lights[0], f.view, f.eye);

  const RayOrigins origins(f.scene, f.view);
  const uint32_t ground_triangles = uint32_t(f.scene.meshes[0].triangleCount());
  int shadowed = 0, lit = 0, ties = 0;
  for (int y = 0; y < f.view.height; ++y) {
    for (int x = 0; x < f.view.width; ++x) {
      const uint32_t id = f.eye.primitive.at(x, y);
      if (id == kNoPrimitive) continue;
      const float v = r.visibility.at(x, y);
      if (id >= ground_triangles) {
        EXPECT_EQ(v, 1.0f) << "the square's lit top at " << x << "," << y;
        continue;
      }
      const dvec3 p(vec3(origins.start(x, y, f.eye.depth.depth.at(x, y), id).origin));
      const dvec3 l(light);
      const dvec3 q = p + (l - p) * ((1.0 - p.y) / (l.y - p.y));
      const double outside = std::max(std::fabs(q.x), std::fabs(q.z)) - 1.0;
      if (std::fabs(outside) < 1e-6) {
        ++ties;
        continue;
      }
      const float expected = outside < 0.0 ? 0.0f : 1.0f;
      EXPECT_EQ(v, expected) << "ground pixel " << x << "," << y << ", crossing at " << q.x
                             << ", " << q.z;
      (expected == 0.0f ? shadowed : lit) += 1;
    }
  }
  EXPECT_GT(shadowed, 1000) << "the square's shadow should cover a good part of the image";
  EXPECT_GT(lit, 1000);
  EXPECT_LE(ties, 2);
}

// Two triangles of a quad share the diagonal x = y in the plane z = 1, the light at the origin.
// A sample exactly on the plane through the light and the diagonal must be shadowed by exactly
// one of them: none would leak light along every quad's diagonal, two would double-count in a
// technique that counts. Values here are small integers, so every edge value is exact.
TEST(AliasFreeOccluderTest, SharedEdgeTieGoesToExactlyOneTriangle) {
  const vec3 l(0.0f);
  const vec3 a(-1, -1, 1), b(1, -1, 1), c(1, 1, 1), d(-1, 1, 1);
  for (const bool flip : {false, true}) {  // both windings: seen from either side
    const auto t1 = flip ? makeOccluderTest(a, c, b, l) : makeOccluderTest(a, b, c, l);
    const auto t2 = flip ? makeOccluderTest(a, d, c, l) : makeOccluderTest(a, c, d, l);
    ASSERT_TRUE(t1 && t2);
    constexpr size_t kN = kOccluderBlock;
    alignas(kOccluderSampleAlignment) double x[kN] = {0.5, 0.5, 0.25, -0.5, 0.25, 0.75, 3, 0};
    alignas(kOccluderSampleAlignment) double y[kN] = {0.5, 0.5, -0.25, 0.25, 0.75, 0.25, 3, 0};
    alignas(kOccluderSampleAlignment) double z[kN] = {2, 0.5, 2, 2, 2, 2, 2, 0};
    // on the diagonal beyond, on it in front, in t1 only, in t2 only, in t2, in t1, outside,
    // the light itself
    const int64_t want1[kOccluderBlock] = {-1, 0, -1, 0, 0, -1, 0, 0};
    const int64_t want2[kOccluderBlock] = {-1, 0, 0, -1, -1, 0, 0, 0};
    for (const bool simd : {false, true}) {
      alignas(kOccluderSampleAlignment) int64_t s1[kOccluderBlock] = {};
      alignas(kOccluderSampleAlignment) int64_t s2[kOccluderBlock] = {};
      markShadowedSamples(*t1, x, y, z, s1, kOccluderBlock, simd);
      markShadowedSamples(*t2, x, y, z, s2, kOccluderBlock, simd);
      EXPECT_NE(s1[0], s2[0]) << "the diagonal tie must go to exactly one, flip " << flip;
      for (size_t i = 1; i < kOccluderBlock; ++i) {
        EXPECT_EQ(s1[i], want1[i]) << "sample " << i << " flip " << flip << " simd " << simd;
        EXPECT_EQ(s2[i], want2[i]) << "sample " << i << " flip " << flip << " simd " << simd;
      }
    }
  }
  // A triangle edge-on to the light casts nothing.
  EXPECT_FALSE(makeOccluderTest(vec3(1, 0, 1), vec3(2, 0, 1), vec3(1, 0, 3), l));
  EXPECT_FALSE(makeOccluderTest(a, a, c, l));  // degenerate
}

// The grid only decides which samples a triangle meets: any tile size gives the same image,
// fewer samples per tile test fewer (triangle, sample) pairs, and a light off to the side of the
// view gets one frustum. If the image changed with the tile size, binning would be losing
// occluders.
TEST(AliasFreeWork, TileSizeChangesWorkNotImage) {
  const testing::EyeFrame f = testing::makeEyeFrame(builtinScene("columns"), 160, 107);
  const TechniqueResult small =
      renderShadows(aliasFree(2), f.scene, f.scene.lights[0], f.view, f.eye);
  const TechniqueResult large =
      renderShadows(aliasFree(256), f.scene, f.scene.lights[0], f.view, f.eye);
  EXPECT_TRUE(small.visibility == large.visibility);
  EXPECT_EQ(small.stats.counter("light_samples"), large.stats.counter("light_samples"));
  EXPECT_GT(small.stats.counter("light_samples"), 0u);
  EXPECT_LE(small.stats.counter("light_samples"), small.stats.z_reads);
  EXPECT_LT(small.stats.counter("sample_tests"), large.stats.counter("sample_tests"));
  EXPECT_GT(small.stats.tiles_tested, large.stats.tiles_tested);
  EXPECT_LT(small.stats.tiles_culled, small.stats.tiles_tested);
}

// Samples in front of the light within 60 degrees of their mean direction share one frustum;
// samples all around it need the cube.
TEST(AliasFreeWork, OneFrustumOrCubeFaces) {
  EXPECT_TRUE(LightGrids({dvec3(0, -1, 0), dvec3(1, -1, 0), dvec3(0, -1, 1)}, 16).singleFrustum());
  const LightGrids around({dvec3(1, 0, 0), dvec3(-1, 0, 0), dvec3(0, -1, 0.1)}, 16);
  EXPECT_FALSE(around.singleFrustum());
  EXPECT_EQ(around.grids().size(), 6u);
  EXPECT_NE(around.tileOf(0), around.tileOf(1));
}

}  // namespace test_alias_free
}  // namespace penumbra
