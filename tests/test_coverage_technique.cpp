// The coverage soft shadow volumes (`coverage`) and Heckbert-Herf (`heckbert-herf`) against the
// ray-traced oracle, the thin-line artifact of Funk 2004 section 4.2, light shapes, and the
// refusal of other shapes by the techniques built on spheres. Tiny frames (96x64 and 120x80),
// oracle at 512 or 1024 rays; release run time about 2.5 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "core/parallel.h"
#include "eye_frame_util.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "shadow_test_util.h"
#include "shadows/coverage_options.h"
#include "shadows/heckbert_herf_options.h"
#include "shadows/reference_options.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/technique.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_coverage_technique {

using testing::EyeFrame;

struct Errors {
  double covered = 0, penumbra = 0;
  size_t penumbra_pixels = 0;
};

// MAE over covered pixels and over the oracle's penumbra pixels (0 < oracle < 1).
Errors errors(const EyeFrame& f, const Image<float>& v, const Image<float>& oracle) {
  Errors e;
  size_t covered = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!(f.eye.depth.depth[i] > 0.0f)) continue;
    const double d = std::fabs(double(v[i]) - double(oracle[i]));
    e.covered += d;
    ++covered;
    if (oracle[i] > 0.0f && oracle[i] < 1.0f) {
      e.penumbra += d;
      ++e.penumbra_pixels;
    }
  }
  e.covered /= double(std::max<size_t>(covered, 1));
  e.penumbra /= double(std::max<size_t>(e.penumbra_pixels, 1));
  return e;
}

Image<float> render(const TechniqueConfig& config, const EyeFrame& f, size_t light = 0) {
  return renderShadows(config, f.scene, f.scene.lights.at(light), f.view, f.eye).visibility;
}

Image<float> oracle(const EyeFrame& f, int rays = 1024) {
  TechniqueConfig o("reference");
  o.options<ReferenceOptions>().rays = rays;
  return render(o, f);
}

// The single-occluder built-in scenes at 120x80 with their 1024-ray oracle, made once for the
// tests below.
struct OracleFrame {
  EyeFrame frame;
  Image<float> truth;
};
const OracleFrame& oracleFrame(const std::string& name) {
  static std::map<std::string, OracleFrame> frames;
  auto it = frames.find(name);
  if (it == frames.end()) {
    OracleFrame f{testing::makeEyeFrame(builtinScene(name), 120, 80), {}};
    f.truth = oracle(f.frame);
    it = frames.emplace(name, std::move(f)).first;
  }
  return it->second;
}

// Single-occluder built-in scenes (the issue's acceptance): the penumbra error of `coverage`
// is at most 0.025 and at most half the three-pass wedges' on the same frames. Failing means
// the per-edge coverage, its sign or the hard pass under it is wrong.
TEST(CoverageTechnique, PenumbraErrorIsSmallAndHalfTheWedges) {
  for (const char* name : {"spheres", "columns"}) {
    const EyeFrame& f = oracleFrame(name).frame;
    const Image<float>& truth = oracleFrame(name).truth;
    const Errors cov = errors(f, render(TechniqueConfig("coverage"), f), truth);
    const Errors wedge = errors(f, render(TechniqueConfig("wedge-3pass"), f), truth);
    std::printf("[ coverage ] %-8s penumbra MAE coverage %.4f  wedge-3pass %.4f (%zu px); "
                "covered %.4f / %.4f\n",
                name, cov.penumbra, wedge.penumbra, cov.penumbra_pixels, cov.covered,
                wedge.covered);
    EXPECT_GT(cov.penumbra_pixels, 200u) << name;
    EXPECT_LE(cov.penumbra, 0.025) << name;
    EXPECT_LE(cov.penumbra, 0.5 * wedge.penumbra) << name;
  }
}

// An open mesh (the Stanford bunny, holes in its base): one facing casts (SolidWithHoles), or
// the front and back sheets' edges would both take the light they cover and the penumbra would
// go black in its inner half. Against the 1024-ray oracle at 96x64: at most half the wedges.
// penumbra error (measured 0.043 against 0.110 at 160x107). Skipped without the shared models.
TEST(CoverageTechnique, OpenMeshPenumbraBeatsTheWedges) {
  const std::string file =
      std::string(PENUMBRA_SOURCE_DIR) + "/tests/data/scenes/stanford-bunny.json";
  if (!testing::sceneModelsPresent(file)) GTEST_SKIP() << "shared models absent: " << file;
  const EyeFrame f = testing::makeEyeFrame(loadSceneFile(file), 96, 64);
  const Image<float> truth = oracle(f);
  const Errors cov = errors(f, render(TechniqueConfig("coverage"), f), truth);
  const Errors wedge = errors(f, render(TechniqueConfig("wedge-3pass"), f), truth);
  std::printf("[ coverage ] stanford-bunny penumbra MAE coverage %.4f  wedge-3pass %.4f (%zu px)\n",
              cov.penumbra, wedge.penumbra, cov.penumbra_pixels);
  EXPECT_GT(cov.penumbra_pixels, 100u);
  EXPECT_LE(cov.penumbra, 0.5 * wedge.penumbra);
}

// The issue's bunny scene bound: bunny-lowres (fetched from npm, or ../shared) against the 1024-ray
// oracle at 160x107, penumbra MAE at most 0.025 and at most half the wedges'. Measured 0.0238
// (wedge-3pass 0.087); before the terminator's edge terms were cut to the light in front of the
// visible surface (insideFractionInHalfPlane) it was 0.0296: failing means that cut is lost or
// the silhouette terms drift. Skipped without the model.
TEST(CoverageTechnique, BunnyPenumbraWithinTheIssuesBound) {
  const std::string file = std::string(PENUMBRA_SOURCE_DIR) + "/scenes/bunny-lowres.json";
  if (!testing::sceneModelsPresent(file)) GTEST_SKIP() << "models absent: " << file;
  const EyeFrame f = testing::makeEyeFrame(loadSceneFile(file), 160, 107);
  const Image<float> truth = oracle(f);
  const Errors cov = errors(f, render(TechniqueConfig("coverage"), f), truth);
  const Errors wedge = errors(f, render(TechniqueConfig("wedge-3pass"), f), truth);
  std::printf("[ coverage ] bunny-lowres penumbra MAE coverage %.4f  wedge-3pass %.4f (%zu px)\n",
              cov.penumbra, wedge.penumbra, cov.penumbra_pixels);
  EXPECT_GT(cov.penumbra_pixels, 300u);
  EXPECT_LE(cov.penumbra, 0.025);
  EXPECT_LE(cov.penumbra, 0.5 * wedge.penumbra);
}

// Disk and rectangle lights (which the wedges refuse) against the oracle sampling the same
// shapes: the same bound. Failing means the frame of a planar light is wrong (its plane, its
// side, or its axes' scale), or its kernel depends on SIMD or threads.
TEST(CoverageTechnique, DiskAndRectangleLightsMatchTheOracle) {
  Scene base = builtinScene("spheres");
  const Light sphere = base.lights.at(0);
  const vec3 down = glm::normalize(vec3(0.3f, -1.0f, 0.2f));
  for (const Light& light :
       {diskLight(sphere.center, down, 2.0f * sphere.radius),
        rectangleLight(sphere.center, vec3(3.0f * sphere.radius, 0.0f, 0.0f),
                       vec3(0.0f, 0.6f * sphere.radius, 1.5f * sphere.radius))}) {
    Scene scene = base;
    scene.lights = {light};
    const EyeFrame f = testing::makeEyeFrame(std::move(scene), 96, 64);
    const Image<float> v = render(TechniqueConfig("coverage"), f);
    const Errors e = errors(f, v, oracle(f, 512));
    // The conformance suite checks threads and SIMD on sphere lights; the planar lights run
    // other kernels (the square's) and frames: one thread, scalar twins, the same bits.
    {
      ThreadLimit one(1);
      RenderContext scalar;
      scalar.simd = false;
      EXPECT_TRUE(v == renderShadows(TechniqueConfig("coverage"), f.scene, f.scene.lights.at(0),
                                     f.view, f.eye, scalar)
                           .visibility)
          << lightShapeName(light.shape);
    }
    std::printf("[ coverage ] %-9s light penumbra MAE %.4f (%zu px), covered %.4f\n",
                lightShapeName(light.shape).c_str(), e.penumbra, e.penumbra_pixels, e.covered);
    EXPECT_GT(e.penumbra_pixels, 100u) << lightShapeName(light.shape);
    EXPECT_LE(e.penumbra, 0.025) << lightShapeName(light.shape);
  }
}

// Funk's section 4.2 artifact: a thin line along the hard shadow's boundary, where the hard
// pass and the coverage pass disagree on which side of a quad a pixel lies, so the pixel is
// off by about a whole light while its neighbours across the boundary are right. Finds pixels
// on a cast hard shadow's boundary (per the hard volume's image; `cast` is 0 where the surface
// faces away from the light, whose terminator is no cast boundary) that are off the oracle by
// more than `step` while both neighbours across it are within step / 2 of it.
size_t boundaryLinePixels(const Image<float>& v, const Image<float>& hard,
                          const Image<float>& truth, const Image<float>& cast, float step) {
  size_t found = 0;
  for (int y = 1; y + 1 < v.height(); ++y) {
    for (int x = 1; x + 1 < v.width(); ++x) {
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        const float h0 = hard.at(x - dx, y - dy), h1 = hard.at(x, y), h2 = hard.at(x + dx, y + dy);
        if (h0 == h1 && h1 == h2) continue;  // no hard boundary at this pixel
        if (cast.at(x - dx, y - dy) == 0.0f || cast.at(x, y) == 0.0f ||
            cast.at(x + dx, y + dy) == 0.0f) {
          continue;
        }
        const auto off = [&](int px, int py) { return std::fabs(v.at(px, py) - truth.at(px, py)); };
        if (off(x, y) > step && off(x - dx, y - dy) < 0.5f * step &&
            off(x + dx, y + dy) < 0.5f * step) {
          ++found;
        }
      }
    }
  }
  return found;
}

TEST(CoverageTechnique, NoThinLineAlongTheHardShadowBoundary) {
  // The detector finds a line when there is one: a smooth ramp (also the truth) with one
  // bright pixel column exactly where the hard image steps.
  {
    Image<float> ramp(16, 8), hard(16, 8);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x) {
        ramp.at(x, y) = float(x) / 15.0f;
        hard.at(x, y) = x < 8 ? 0.0f : 1.0f;
      }
    const Image<float> truth = ramp, cast(16, 8, 1.0f);
    ASSERT_EQ(boundaryLinePixels(ramp, hard, truth, cast, 0.2f), 0u);
    for (int y = 0; y < 8; ++y) ramp.at(7, y) = 1.0f;
    ASSERT_GE(boundaryLinePixels(ramp, hard, truth, cast, 0.2f), 6u);
  }
  for (const char* name : {"spheres", "columns"}) {
    const EyeFrame& f = oracleFrame(name).frame;
    const Image<float> hard = render(TechniqueConfig("volume"), f);
    const Image<float> cov = render(TechniqueConfig("coverage"), f);
    Image<float> cast;
    resolveVisibility(f.scene, f.scene.lights.at(0), f.view, f.eye, cast,
                      [](int, int) { return 1.0f; });
    EXPECT_EQ(boundaryLinePixels(cov, hard, oracleFrame(name).truth, cast, 0.2f), 0u) << name;
  }
}

// Heckbert-Herf converges toward the oracle at least like N^-1/2: each 4x more renders at
// least halve the penumbra error (with 20% slack for noise). A disk light, so that the N points
// and the oracle's rays sample the same shape (a sphere is taken as the disk facing the scene,
// a small bias that would flatten the curve).
TEST(HeckbertHerf, ErrorFallsLikeOneOverSqrtN) {
  Scene scene = builtinScene("spheres");
  const Light sphere = scene.lights.at(0);
  scene.lights = {diskLight(sphere.center, vec3(0.0f, -1.0f, 0.0f), 1.5f * sphere.radius)};
  const EyeFrame f = testing::makeEyeFrame(std::move(scene), 96, 64);
  const Image<float> truth = oracle(f);
  double previous = 0.0;
  for (const int n : {4, 16, 64}) {
    TechniqueConfig hh("heckbert-herf");
    hh.options<HeckbertHerfOptions>().samples = n;
    const Errors e = errors(f, render(hh, f), truth);
    std::printf("[ hh       ] N=%2d penumbra MAE %.4f (%zu px)\n", n, e.penumbra,
                e.penumbra_pixels);
    EXPECT_GT(e.penumbra_pixels, 100u);
    if (n > 4) {
      EXPECT_LE(e.penumbra, 0.6 * previous) << "N " << n;
    }
    previous = e.penumbra;
  }
}

// Wedges and shadow maps are built on spheres: another shape is refused with a message naming
// the technique and the shape, never rendered as a sphere (`exact` takes every shape).
TEST(LightShapes, SphereOnlyTechniquesRefuseOtherShapes) {
  Scene scene = builtinScene("spheres");
  const Light sphere = scene.lights.at(0);
  scene.lights = {rectangleLight(sphere.center, vec3(0.4f, 0, 0), vec3(0, 0, 0.4f))};
  const EyeFrame f = testing::makeEyeFrame(std::move(scene), 32, 24);
  for (const char* name : {"wedge-3pass", "wedge-1pass", "wedge-2002", "shadow-map"}) {
    const std::string message = test::errorMessage([&] { render(TechniqueConfig(name), f); });
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("rectangle"), std::string::npos) << message;
  }
  for (const char* name : {"coverage", "exact", "heckbert-herf", "reference", "volume"}) {
    EXPECT_NO_THROW(render(TechniqueConfig(name), f)) << name;
  }
}

// Scene files: "shape" with its keys; keys of another shape, a bad normal or skewed edges are
// refused with the key path.
TEST(LightShapes, SceneFilesReadShapesAndRefuseBadOnes) {
  const auto scene = [](const std::string& light) {
    return R"({"meshes": [{"generator": "plane", "half_size": 4}], "lights": [)" + light + "]}";
  };
  const Scene disk = parseSceneJson(
      scene(R"({"center": [0, 5, 0], "radius": 0.5, "shape": "disk", "normal": [0, -2, 0]})"),
      "disk.json", ".");
  EXPECT_EQ(disk.lights[0].shape, LightShape::Disk);
  EXPECT_FLOAT_EQ(disk.lights[0].normal.y, -1.0f);
  const Scene rect = parseSceneJson(
      scene(R"({"center": [0, 5, 0], "shape": "rectangle", "u": [2, 0, 0], "v": [0, 0, 1]})"),
      "rect.json", ".");
  EXPECT_EQ(rect.lights[0].shape, LightShape::Rectangle);
  EXPECT_NEAR(rect.lights[0].radius, 0.5 * std::sqrt(5.0), 1e-6);
  EXPECT_NO_THROW(checkLightShape(rect.lights[0]));
  const std::pair<std::string, std::string> bad[] = {
      {R"({"center": [0, 5, 0], "shape": "cone"})", "unknown light shape"},
      {R"({"center": [0, 5, 0], "shape": "disk", "radius": 1})", "normal"},
      {R"({"center": [0, 5, 0], "shape": "disk", "radius": 1, "normal": [0, 0, 0]})", "non-zero"},
      {R"({"center": [0, 5, 0], "radius": 1, "normal": [0, 1, 0]})", "only a disk"},
      {R"({"center": [0, 5, 0], "shape": "rectangle", "u": [1, 0, 0], "v": [1, 0, 1]})",
       "orthogonal"},
      {R"({"center": [0, 5, 0], "shape": "rectangle", "u": [1, 0, 0], "v": [0, 0, 1], "radius": 2})",
       "no radius"},
  };
  for (const auto& [light, expected] : bad) {
    const std::string message =
        test::errorMessage([&] { parseSceneJson(scene(light), "bad.json", "."); });
    EXPECT_NE(message.find(expected), std::string::npos) << light << ": " << message;
    EXPECT_NE(message.find("lights[0]"), std::string::npos) << message;
  }
}

}  // namespace test_coverage_technique
}  // namespace penumbra

namespace penumbra {
namespace test_coverage_technique {

// Scenes built in code are checked too (Scene::finalize): a disk with a zero normal, a skewed
// rectangle, or a rectangle whose radius is not its half diagonal is refused, naming the light.
TEST(LightShapes, FinalizeChecksShapes) {
  const auto finalizeWith = [](const Light& light) {
    Scene scene = builtinScene("spheres");
    scene.lights = {light};
    scene.finalize();
  };
  const vec3 c(0.0f, 5.0f, 0.0f);
  EXPECT_NO_THROW(finalizeWith(diskLight(c, vec3(0, -1, 0), 0.5f)));
  EXPECT_NO_THROW(finalizeWith(rectangleLight(c, vec3(1, 0, 0), vec3(0, 0, 2))));
  Light bad_disk = diskLight(c, vec3(0, -1, 0), 0.5f);
  bad_disk.normal = vec3(0.0f);
  Light skewed = rectangleLight(c, vec3(1, 0, 0), vec3(1, 0, 1));
  Light wrong_radius = rectangleLight(c, vec3(1, 0, 0), vec3(0, 0, 2));
  wrong_radius.radius = 0.3f;
  const std::pair<Light, std::string> bad[] = {
      {bad_disk, "normal"}, {skewed, "orthogonal"}, {wrong_radius, "half its diagonal"}};
  for (const auto& [light, expected] : bad) {
    const std::string message = test::errorMessage([&] { finalizeWith(light); });
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_NE(message.find("light 0"), std::string::npos) << message;
  }
}

}  // namespace test_coverage_technique
}  // namespace penumbra
