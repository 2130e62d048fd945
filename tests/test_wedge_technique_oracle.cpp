// Penumbra wedge techniques against the ray-traced oracle (`reference`, fixed
// seed): mean absolute visibility error over the covered pixels and over the oracle's penumbra
// (0 < v < 1), the eye inside a shadow or inside a wedge (z-fail, 2004 paper, section 5), and
// every shared model scene without light leaks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "open_mesh_util.h"
#include "raster/eye_pass.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/normals.h"
#include "scene/scene_file.h"
#include "shadow_test_util.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/stages/silhouettes/silhouette.h"
#include "shadows/technique.h"
#include "shadows/wedge/li_buffer.h"
#include "shadows/wedge/wedge.h"
#include "shadows/wedge/light_wedges.h"
#include "shadows/wedge/wedge_technique.h"

namespace penumbra {
namespace test_wedge_technique_oracle {

constexpr WedgeAlgorithm kWedgeKinds[] = {WedgeAlgorithm::Original2002, WedgeAlgorithm::ThreePass,
                                           WedgeAlgorithm::SinglePass};

// The acceptance bounds (the issue): over covered pixels, and over the oracle's penumbra.
constexpr double kMaxMaeCovered = 0.03;
constexpr double kMaxMaePenumbra = 0.10;

struct Frame {
  Scene scene;
  View view;
  EyeBuffers eye;
  TechniqueResult oracle;
};

Frame makeFrame(Scene scene, int width, int height, int rays) {
  Frame f;
  f.scene = std::move(scene);
  f.view = f.scene.camera.makeView(width, height);
  Stats stats;
  f.eye = renderEyePass(f.scene, f.view, stats);
  TechniqueConfig o("reference");
  o.options<ReferenceOptions>().rays = rays;
  o.options<ReferenceOptions>().seed = 1;
  f.oracle = renderShadows(o, f.scene, f.scene.lights.at(0), f.view, f.eye);
  return f;
}

struct OracleError {
  double covered = 0;   // MAE over covered pixels
  double penumbra = 0;  // MAE over the oracle's penumbra pixels
  size_t penumbra_pixels = 0;
  double leak_fraction = 0;  // covered pixels more than 0.5 brighter than the oracle
  size_t largest_leak = 0;   // pixels in the largest 4-connected group of those
};

OracleError measure(const Frame& f, const Image<float>& v) {
  const Image<float>& oracle = f.oracle.visibility;
  const int w = v.width(), h = v.height();
  double sum = 0, sum_penumbra = 0;
  size_t covered = 0, leaks = 0;
  OracleError e;
  Image<uint8_t> leak(w, h, 0);
  for (size_t i = 0; i < v.size(); ++i) {
    if (!(f.eye.depth.depth[i] > 0.0f)) continue;
    const double d = double(v[i]) - double(oracle[i]);
    sum += std::fabs(d);
    ++covered;
    if (d > 0.5) {
      leak[i] = 1;
      ++leaks;
    }
    if (oracle[i] > 0.0f && oracle[i] < 1.0f) {
      sum_penumbra += std::fabs(d);
      ++e.penumbra_pixels;
    }
  }
  e.covered = covered ? sum / double(covered) : 0.0;
  e.penumbra = e.penumbra_pixels ? sum_penumbra / double(e.penumbra_pixels) : 0.0;
  e.leak_fraction = covered ? double(leaks) / double(covered) : 0.0;
  // Largest group of leaking pixels: a missing volume or wedge leaks light over a region;
  // rounding along a boundary or a thin wedge seam only over scattered pixels and lines.
  std::vector<int> stack;
  for (int start = 0; start < w * h; ++start) {
    if (leak[size_t(start)] != 1) continue;
    size_t size = 0;
    stack.assign(1, start);
    leak[size_t(start)] = 2;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      ++size;
      const int x = p % w, y = p / w;
      const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
        const size_t q = size_t(n[1]) * size_t(w) + size_t(n[0]);
        if (leak[q] != 1) continue;
        leak[q] = 2;
        stack.push_back(int(q));
      }
    }
    e.largest_leak = std::max(e.largest_leak, size);
  }
  return e;
}

TechniqueResult render(const Frame& f, WedgeAlgorithm kind, VolumeMode mode = VolumeMode::Auto) {
  WedgeOptions o;
  o.volume_mode = mode;
  return renderShadows(TechniqueConfig(wedgeTechniqueName(kind), o), f.scene,
                       f.scene.lights.at(0), f.view, f.eye);
}

TechniqueResult renderHard(const Frame& f) {
  return renderShadows(TechniqueConfig("volume"), f.scene, f.scene.lights.at(0), f.view, f.eye);
}

void report(const std::string& scene, const std::string& what, const OracleError& e) {
  std::printf("[ wedges   ] %-22s %-16s MAE covered %.4f  penumbra %.4f (%zu px)  leaks %.3f%% "
              "(largest %zu px)\n",
              scene.c_str(), what.c_str(), e.covered, e.penumbra, e.penumbra_pixels,
              100.0 * e.leak_fraction, e.largest_leak);
  ::testing::Test::RecordProperty(scene + "_" + what + "_mae_covered", std::to_string(e.covered));
  ::testing::Test::RecordProperty(scene + "_" + what + "_mae_penumbra", std::to_string(e.penumbra));
}

// The paper scenes and a real mesh at 320 x 214 against 1024 oracle rays per pixel (its noise
// adds about 0.01 to the penumbra error): every variant within the acceptance bounds, and far
// better than hard shadows in the penumbra, which shows the penumbra is really there.
TEST(WedgeOracle, PaperScenesAndBunnyWithinBounds) {
  std::vector<std::string> names = {"spheres", "columns"};
  if (testing::sharedModel("bunny-lowres.obj").empty()) {
    std::printf("[ SKIPPED  ] bunny-lowres: shared models not found in %s\n",
                modelsDirectory().c_str());
  } else {
    names.push_back(std::string(PENUMBRA_SOURCE_DIR) + "/scenes/bunny-lowres.json");
  }
  for (const std::string& name : names) {
    const Frame f = makeFrame(loadScene(name), 320, 214, 1024);
    const std::string scene = f.scene.name.empty() ? name : f.scene.name;
    const OracleError hard = measure(f, renderHard(f).visibility);
    report(scene, "volume (hard)", hard);
    for (WedgeAlgorithm kind : kWedgeKinds) {
      const OracleError e = measure(f, render(f, kind).visibility);
      report(scene, wedgeTechniqueName(kind), e);
      EXPECT_LE(e.covered, kMaxMaeCovered) << scene << " " << wedgeTechniqueName(kind);
      EXPECT_LE(e.penumbra, kMaxMaePenumbra) << scene << " " << wedgeTechniqueName(kind);
      EXPECT_LT(e.penumbra, 0.5 * hard.penumbra) << scene << " " << wedgeTechniqueName(kind);
    }
  }
}

// A table top (a closed slab) over the ground under a large light: a wide umbra under it, a
// penumbra band around it. The eye is placed under the table (inside the umbra volume), in the
// penumbra band (inside a wedge: none of its faces is front-facing), and outside everything.
Scene tableScene(vec3 eye, vec3 target) {
  Scene s;
  s.name = "table";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0.0f), 20.0f));
  s.meshes.push_back(makeBox(vec3(-2.0f, 1.5f, -2.0f), vec3(2.0f, 1.8f, 2.0f)));
  s.lights.push_back(Light{vec3(0.0f, 10.0f, 0.0f), 1.5f, vec3(1.0f), 1.0f});
  s.camera.position = eye;
  s.camera.target = target;
  s.camera.fov_y = 70.0f;
  s.camera.near_plane = 0.05f;
  s.finalize();
  return s;
}

// 2004 paper, section 5: with the eye inside a shadow region, counting from the eye (z-pass)
// starts wrong, and z-fail with capped volumes and the back-facing wedge faces must be used.
// Auto must pick z-fail (its LI buffer is the forced z-fail one), match the oracle as well as
// with the eye outside, and forced z-pass must visibly fail (which shows the test can catch a
// wrong choice). The 2002 algorithm counts from the eye only (2002 paper, section 8) and is not
// run here. 256 oracle rays (noise about 0.02 in the penumbra) keep this test fast.
TEST(WedgeOracle, EyeInsideShadowOrWedgeUsesZFail) {
  struct Case {
    const char* what;
    vec3 eye, target;
    bool inside;     // the eye is inside the umbra volume or a wedge
    bool in_wedge;   // the eye is inside a wedge
  };
  // Penumbra band at the eye's height 0.8 beside the x = 2 edge: x in [2.06, 2.43] (edge at
  // y = 1.8, light radius 1.5 at height 10); the hard boundary from the centre is x = 2.24.
  const Case cases[] = {
      {"eye outside", vec3(7.0f, 4.0f, 7.0f), vec3(0.0f, 0.5f, 0.0f), false, false},
      {"eye in umbra", vec3(0.3f, 0.7f, 0.2f), vec3(4.0f, 0.0f, 3.0f), true, false},
      {"eye in wedge", vec3(2.24f, 0.8f, 0.0f), vec3(-1.0f, 0.0f, 4.0f), true, true}};
  for (const Case& c : cases) {
    const Frame f = makeFrame(tableScene(c.eye, c.target), 240, 160, 256);
    const LightWedges wedges =
        buildLightWedges(LightWedgesOptions{}, f.scene, f.scene.lights[0], f.view, f.eye);
    bool eye_in_wedge = false;
    for (const Wedge& w : wedges.wedges) {
      const dvec3 e(c.eye);  // the wedge is the region inside its four planes (light_wedges.cpp)
      eye_in_wedge = eye_in_wedge || (w.front.eval(e) >= 0.0 && w.back.eval(e) >= 0.0 &&
                                      w.left.eval(e) >= 0.0 && w.right.eval(e) >= 0.0);
    }
    EXPECT_EQ(eye_in_wedge, c.in_wedge) << c.what;
    size_t umbra = 0, lit = 0, penumbra = 0;
    for (size_t i = 0; i < f.oracle.visibility.size(); ++i) {
      if (!(f.eye.depth.depth[i] > 0.0f)) continue;
      const float v = f.oracle.visibility[i];
      umbra += v == 0.0f;
      lit += v == 1.0f;
      penumbra += v > 0.0f && v < 1.0f;
    }
    EXPECT_GT(umbra, 500u) << c.what;
    EXPECT_GT(lit, 500u) << c.what;
    EXPECT_GT(penumbra, 500u) << c.what;
    for (WedgeAlgorithm kind : {WedgeAlgorithm::ThreePass, WedgeAlgorithm::SinglePass}) {
      const std::string what = std::string(c.what) + " " + wedgeTechniqueName(kind);
      WedgeOptions o;
      const Light& light = f.scene.lights[0];
      const WedgeLi automatic = renderWedgeLi(kind, o, f.scene, light, f.view, f.eye);
      o.volume_mode = VolumeMode::ZFail;
      const WedgeLi zfail = renderWedgeLi(kind, o, f.scene, light, f.view, f.eye);
      if (c.inside) {
        EXPECT_TRUE(automatic.li == zfail.li) << what << ": auto did not pick z-fail";
      }
      const OracleError e = measure(f, render(f, kind).visibility);
      report("table", what, e);
      EXPECT_LE(e.covered, kMaxMaeCovered) << what;
      EXPECT_LE(e.penumbra, kMaxMaePenumbra) << what;
      const OracleError zpass = measure(f, render(f, kind, VolumeMode::ZPass).visibility);
      report("table", what + " z-pass", zpass);
      if (c.inside) {
        EXPECT_GT(zpass.covered, 10.0 * kMaxMaeCovered) << what << ": z-pass should fail";
      } else {
        EXPECT_LE(zpass.covered, kMaxMaeCovered) << what;
      }
    }
  }
}

// An open mesh on a floor: the scene the open-mesh tests below share.
Scene openMeshScene(const char* name, Mesh mesh, vec3 light, float radius, vec3 eye,
                    vec3 target) {
  Scene s;
  s.name = name;
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0.0f), 20.0f));
  s.meshes.push_back(std::move(mesh));
  s.lights.push_back(Light{light, radius, vec3(1.0f), 1.0f});
  s.camera.position = eye;
  s.camera.target = target;
  s.camera.fov_y = 50.0f;
  s.finalize();
  return s;
}

// An open dome (a hemisphere shell, rim down) over the floor, lit from the side: its
// terminator is a fold where light-facing and facing-away triangles meet. Cast two-sided, as
// the hard volume does, the fold gets two coincident wedges and the inner half of the
// penumbra goes black: penumbra error 0.18 (all three variants, 256 rays, noise about 0.02).
// Cast one-sided (silhouette.h, SolidWithHoles) it is measured at 0.062. Bound: the acceptance
// bound 0.10; failing it means open meshes darken their penumbrae twice again.
TEST(WedgeOracle, OpenMeshPenumbraIsNotDoubled) {
  const Frame f = makeFrame(openMeshScene("dome", testing::openSphere(vec3(0.0f, 1.0f, 0.0f), 1.0f,
                                                                      0.5 * std::numbers::pi),
                                          vec3(4.0f, 9.0f, 3.0f), 1.5f, vec3(-3.0f, 6.0f, 6.0f),
                                          vec3(-1.0f, 0.0f, -1.0f)),
                            240, 160, 256);
  ASSERT_FALSE(f.scene.meshes[1].closed);
  for (WedgeAlgorithm kind : kWedgeKinds) {
    const OracleError e = measure(f, render(f, kind).visibility);
    report("dome", wedgeTechniqueName(kind), e);
    EXPECT_GT(e.penumbra_pixels, 500u);
    EXPECT_LE(e.covered, kMaxMaeCovered) << wedgeTechniqueName(kind);
    EXPECT_LE(e.penumbra, kMaxMaePenumbra) << wedgeTechniqueName(kind);
  }
}

// The light inside an open mesh (a globe with a hole at the bottom, as a lamp shade): the
// floor is lit in a pool under the hole and shadowed by the globe everywhere else. Every
// triangle faces away from the light, so casting the light-facing side alone (the rule for an
// open mesh seen from outside) would leave the whole floor lit: covered error 0.88. The winding
// number picks the facing-away side; measured 0.003 covered, 0.039 penumbra. The eye is
// in the globe's shadow, so the 2002 algorithm (z-pass only) is not run.
TEST(WedgeOracle, LightInsideOpenMeshStillCasts) {
  const vec3 centre(0.0f, 2.5f, 0.0f);
  const Frame f = makeFrame(openMeshScene("globe", testing::openSphere(centre, 1.0f,
                                                                       0.75 * std::numbers::pi),
                                          centre, 0.15f, vec3(5.0f, 6.0f, 7.0f),
                                          vec3(0.0f, 0.0f, 0.0f)),
                            240, 160, 256);
  size_t umbra = 0, lit = 0;
  for (size_t i = 0; i < f.oracle.visibility.size(); ++i) {
    if (!(f.eye.depth.depth[i] > 0.0f)) continue;
    umbra += f.oracle.visibility[i] == 0.0f;
    lit += f.oracle.visibility[i] == 1.0f;
  }
  EXPECT_GT(umbra, 2000u);
  EXPECT_GT(lit, 2000u);
  for (WedgeAlgorithm kind : {WedgeAlgorithm::ThreePass, WedgeAlgorithm::SinglePass}) {
    const OracleError e = measure(f, render(f, kind).visibility);
    report("globe", wedgeTechniqueName(kind), e);
    EXPECT_LE(e.covered, kMaxMaeCovered) << wedgeTechniqueName(kind);
    EXPECT_LE(e.penumbra, kMaxMaePenumbra) << wedgeTechniqueName(kind);
  }
}

// A closed slab whose outline (seen from above) is a thin triangle: its tip at +x is a
// 30 degree corner (split: below 60 degrees, wedge_sides.cpp), its base at -x.
// Counter-clockwise from outside.
Mesh sliverPrism(float y0, float y1) {
  Mesh m;
  m.name = "sliver-prism";
  const vec2 outline[3] = {vec2(1.5f, 0.0f), vec2(-1.5f, -0.8f), vec2(-1.5f, 0.8f)};
  for (const float y : {y0, y1})
    for (const vec2& p : outline) m.positions.push_back(vec3(p.x, y, p.y));
  // The outline runs counter-clockwise seen from above: top 3, 4, 5, bottom reversed.
  m.indices = {3, 4, 5, 0, 2, 1};
  for (uint32_t i = 0; i < 3; ++i) {
    const uint32_t j = (i + 1) % 3;
    for (const uint32_t v : {i, j, j + 3, i, j + 3, i + 3}) m.indices.push_back(v);
  }
  computeCornerNormals(m);
  return m;
}

// The notch at a split silhouette vertex (wedge.cpp, wedge_gap.h): the prism's 9.5 degree tip
// is split (each wedge ends on its own plane, a connector umbra quad closes the volume), and
// the region between the two end planes, inside the connector's fan, lies inside the umbra
// volume. Covered by no wedge it rendered black: on the floor inside the notch (474 pixels) the
// three variants were 0.95 darker than the oracle on average (256 rays), every pixel more than
// 0.25 darker. The gap wedge fills it from the connector (s = 1) down to the hard direction:
// measured 0.11 darker on average, 12 % of the pixels more than 0.25 darker (its
// side-to-side interpolation is not the true visibility of a sharp tip). Bounds: 0.2 and
// 25 %; failing them means the notch is dark again, the dashes in bunny-lowres's ear shadows.
TEST(WedgeOracle, SplitVertexNotchIsNotDark) {
  const Frame f = makeFrame(openMeshScene("sliver", sliverPrism(1.0f, 1.1f),
                                          vec3(0.0f, 6.0f, 0.0f), 1.2f, vec3(2.1f, 0.9f, 0.5f),
                                          vec3(1.85f, 0.0f, 0.0f)),
                            240, 160, 256);
  const Mesh& prism = f.scene.meshes[1];
  ASSERT_TRUE(prism.closed);
  const Light& light = f.scene.lights[0];
  const WedgeSet ws = buildWedges(
      prism, findSilhouette(prism, f.scene.adjacency[1], light.center), light);
  ASSERT_EQ(ws.split_vertices, 1u);
  // The notch, from the connector alone: behind both end planes, inside the connector's fan.
  const UmbraQuad* connector = nullptr;
  for (const UmbraQuad& q : ws.umbra)
    if (q.va == q.vb) connector = &q;
  ASSERT_NE(connector, nullptr);
  const Wedge *in = nullptr, *out = nullptr;
  for (const Wedge& w : ws.wedges) {
    if (w.unit_edge == connector->prev) in = &w;
    if (w.unit_edge == connector->next) out = &w;
  }
  ASSERT_TRUE(in != nullptr && out != nullptr);
  const dvec3 v(prism.positions[connector->va]), c(light.center);
  dvec3 fan = glm::normalize(glm::cross(dvec3(connector->inf_a), dvec3(connector->inf_b)));
  if (glm::dot(fan, v - c) < 0.0) fan = -fan;
  size_t notch = 0;
  std::vector<double> darker(std::size(kWedgeKinds), 0.0);
  std::vector<size_t> much_darker(std::size(kWedgeKinds), 0);
  std::vector<Image<float>> images;
  for (WedgeAlgorithm kind : kWedgeKinds) images.push_back(render(f, kind).visibility);
  for (int y = 0; y < f.view.height; ++y) {
    for (int x = 0; x < f.view.width; ++x) {
      const size_t i = size_t(y) * size_t(f.view.width) + size_t(x);
      const float depth = f.eye.depth.depth[i];
      if (!(depth > 0.0f)) continue;
      const dvec3 p = f.view.unproject(x, y, depth);
      if (!(p.y < 0.01 && in->right.eval(p) < 0.0 && out->left.eval(p) < 0.0 &&
            glm::dot(fan, p - v) > 0.0))
        continue;
      ++notch;
      for (size_t k = 0; k < images.size(); ++k) {
        const double d = double(f.oracle.visibility[i]) - double(images[k][i]);
        darker[k] += d;
        much_darker[k] += d > 0.25;
      }
    }
  }
  ASSERT_GT(notch, 100u);
  for (size_t k = 0; k < images.size(); ++k) {
    const double mean = darker[k] / double(notch);
    const double fraction = double(much_darker[k]) / double(notch);
    std::printf("[ wedges   ] sliver notch %-12s %zu px, darker than the oracle by %.3f on "
                "average, %.1f %% by more than 0.25\n",
                wedgeTechniqueName(kWedgeKinds[k]).c_str(), notch, mean, 100.0 * fraction);
    EXPECT_LT(mean, 0.2) << wedgeTechniqueName(kWedgeKinds[k]);
    EXPECT_LT(fraction, 0.25) << wedgeTechniqueName(kWedgeKinds[k]);
  }
}

// Every mesh of ../shared/models in its scene file, open and non-manifold ones included, with
// every variant (the 2002 one where the eye is outside every volume: it counts from the eye
// only), against 64 oracle rays at 240 x 160. No crash, and no light leaks: a missing wedge or
// volume face lets light through over a region (z-pass with the eye in the table's umbra, above:
// 59 % of the pixels, the largest group 14013 pixels), so the largest 4-connected group of
// pixels more than 0.5 brighter than the oracle must stay small, and so must their fraction.
// Measured: largest group 9 pixels and 0.40 % on the armadillo, whose thousands of tiny
// overlapping wedges streak; at most 4 pixels and 0.08 % elsewhere. Bounds: 40 pixels, 0.8 %.
// The covered-pixel error is bounded too (measured at most 0.019); the penumbra error is only
// reported: on dense meshes and inconsistently oriented open ones it is as large as hard
// shadows' (overlapping wedges, 2002 paper section 8; two-sided casters, silhouette.h).
TEST(WedgeOracle, SharedModelScenesRenderWithoutLightLeaks) {
  if (testing::sharedModel("bunny-lowres.obj").empty())
    GTEST_SKIP() << "shared models not found in " << modelsDirectory();
  constexpr double kMaxCovered = 0.03;
  constexpr double kMaxLeakFraction = 0.008;
  constexpr size_t kMaxLeakGroup = 40;
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& dir : testing::sceneFileFolders())
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), 13u);
  for (const std::filesystem::path& file : files) {
    if (!testing::sceneModelsPresent(file)) {
      std::printf("[ SKIPPED  ] %s: its models are not in %s\n", file.filename().c_str(),
                  modelsDirectory().c_str());
      continue;
    }
    const Frame f = makeFrame(loadSceneFile(file.string()), 240, 160, 64);
    const std::string scene = file.stem().string();
    const bool eye_outside =
        render(f, WedgeAlgorithm::ThreePass).visibility ==
        render(f, WedgeAlgorithm::ThreePass, VolumeMode::ZPass).visibility;
    for (WedgeAlgorithm kind : kWedgeKinds) {
      if (kind == WedgeAlgorithm::Original2002 && !eye_outside) continue;
      const OracleError e = measure(f, render(f, kind).visibility);
      report(scene, wedgeTechniqueName(kind), e);
      EXPECT_LE(e.covered, kMaxCovered) << scene << " " << wedgeTechniqueName(kind);
      EXPECT_LE(e.leak_fraction, kMaxLeakFraction) << scene << " " << wedgeTechniqueName(kind);
      EXPECT_LE(e.largest_leak, kMaxLeakGroup) << scene << " " << wedgeTechniqueName(kind);
    }
  }
}

}  // namespace test_wedge_technique_oracle
}  // namespace penumbra
