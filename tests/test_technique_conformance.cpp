// The conformance suite: every registered technique (shadows/technique.h), the table's and any a
// program registers, is held to the contract and to what it claims, without the suite being
// told about it. A technique added later gets all of this by being registered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "eye_frame_util.h"
#include "hard_casters.h"
#include "metrics/shadow_boundary.h"
#include "oracle_cache.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_technique_conformance {

// A technique this test binary brings: every point lit that faces the light. Its one
// registration below is all it takes to be run through the whole suite (the instantiation at
// the end of this file lists the registered techniques). It claims what it does: hard shadows,
// no accuracy at all.
class AllLit final : public PreparedTechnique {
 public:
  explicit AllLit(const Scene& scene) : scene_(scene) {}
  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext&) const override {
    TechniqueResult result;
    resolveVisibility(scene_, light, view, eye, result.visibility, [](int, int) { return 1.0f; });
    return result;
  }

 private:
  const Scene& scene_;
};

struct AllLitOptions {};

TechniqueInfo allLitTechnique() {
  TechniqueInfo info;
  info.name = "test-all-lit";
  info.summary = "every point that faces the light is lit (conformance suite's own technique)";
  info.options = OptionTableBuilder<AllLitOptions>().build();
  info.prepare = [](const std::any&, const Scene& scene) {
    return std::make_unique<AllLit>(scene);
  };
  return info;
}

const bool all_lit_registered = (registerTechnique(allLitTechnique()), true);

constexpr int kWidth = 160, kHeight = 107;

using Frame = testing::EyeFrame;

Frame makeFrame(Scene scene, int width = kWidth, int height = kHeight) {
  return testing::makeEyeFrame(std::move(scene), width, height);
}

struct LightsResult {
  std::vector<TechniqueResult> lights;
};

LightsResult renderAll(const TechniqueConfig& config, const Frame& f,
                       const RenderContext& context = {}) {
  const std::unique_ptr<PreparedTechnique> prepared = prepareTechnique(config, f.scene);
  LightsResult r;
  for (const Light& light : f.scene.lights)
    r.lights.push_back(prepared->render(light, f.view, f.eye, context));
  return r;
}

// The oracle's visibility for a built-in scene, rendered once per scene and kind: 1024 rays
// over the light for soft techniques, one ray to the centre for hard ones. Only the visibility
// is kept (the suite compares nothing else with it), on disk too (oracle_cache.h): every
// technique's test process would otherwise trace the same oracle again.
const LightsResult& oracle(const std::string& scene, const Frame& f, bool soft) {
  static std::map<std::string, LightsResult> cache;
  const std::string key = scene + (soft ? "-soft" : "-hard");
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  const std::string disk_key = fmt::format("conformance-{}-{}x{}", key, f.view.width, f.view.height);
  LightsResult r;
  if (auto images = testing::loadOracleImages(disk_key, f.scene.lights.size(), f.view.width,
                                              f.view.height)) {
    for (Image<float>& image : *images) r.lights.push_back({std::move(image), {}, {}, {}});
  } else {
    TechniqueConfig config("reference");
    config.options<ReferenceOptions>().rays = 1024;
    config.options<ReferenceOptions>().hard = !soft;
    r = renderAll(config, f);
    std::vector<const Image<float>*> stored;
    for (const TechniqueResult& light : r.lights) stored.push_back(&light.visibility);
    testing::storeOracleImages(disk_key, stored);
  }
  return cache.emplace(key, std::move(r)).first->second;
}

const Frame& builtinFrame(const std::string& name) {
  static std::map<std::string, Frame> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, makeFrame(builtinScene(name))).first;
  return it->second;
}

struct OracleError {
  double covered = 0, penumbra = 0;
  size_t penumbra_pixels = 0;
};

// Mean absolute error over pixels showing geometry, and over the oracle's penumbra.
OracleError oracleError(const Frame& f, const LightsResult& technique, const LightsResult& truth) {
  OracleError e;
  size_t covered = 0;
  for (size_t l = 0; l < truth.lights.size(); ++l) {
    const Image<float>& a = technique.lights[l].visibility;
    const Image<float>& b = truth.lights[l].visibility;
    for (size_t i = 0; i < b.size(); ++i) {
      if (!(f.eye.depth.depth[i] > 0.0f)) continue;
      const double d = std::fabs(double(a[i]) - double(b[i]));
      e.covered += d;
      ++covered;
      if (b[i] > 0.0f && b[i] < 1.0f) {
        e.penumbra += d;
        ++e.penumbra_pixels;
      }
    }
  }
  e.covered = covered ? e.covered / double(covered) : 0.0;
  e.penumbra = e.penumbra_pixels ? e.penumbra / double(e.penumbra_pixels) : 0.0;
  return e;
}

bool sameOutput(const LightsResult& a, const LightsResult& b, std::string& what) {
  if (a.lights.size() != b.lights.size()) {
    what = "light count";
    return false;
  }
  for (size_t l = 0; l < a.lights.size(); ++l) {
    if (!(a.lights[l].visibility == b.lights[l].visibility)) {
      what = "visibility of light " + std::to_string(l);
      return false;
    }
    if (!a.lights[l].stats.sameCounters(b.lights[l].stats)) {
      what = "counters of light " + std::to_string(l);
      return false;
    }
  }
  return true;
}

// Whether a technique claims the hard volume's image where the light has no radius: rasterized
// and not claiming the oracle's own answer (`exact` techniques differ from the volume at ties),
// and either hard within twice `volume`'s error bound or soft and exactly the volume at radius 0.
bool claimsVolumesImage(const TechniqueTraits& traits) {
  if (traits.ray_traced || traits.exact) return false;
  return traits.soft
             ? traits.zero_radius_mae_bound == 0.0
             : traits.covered_mae_bound <= 2.0 * findTechnique("volume").traits.covered_mae_bound;
}

class TechniqueConformance : public ::testing::TestWithParam<std::string> {
 protected:
  const TechniqueInfo& info() const { return findTechnique(GetParam()); }
};

// Bad option values must be refused with a message that names the technique and the option,
// and leave the configuration as it was; an option the technique does not have is refused
// too. If this failed, a typo on the command line would render with a default nobody chose.
TEST_P(TechniqueConformance, RejectsBadOptionsWithAMessage) {
  TechniqueConfig config(GetParam());
  const auto expectRefused = [&](const std::string& option, const std::string& value) {
    const std::string before = config.info().options.find(option)
                                   ? config.get(option)
                                   : std::string();
    try {
      config.set(option, value);
      ADD_FAILURE() << GetParam() << ": --" << option << " '" << value << "' was accepted";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(GetParam()), std::string::npos) << message;
      EXPECT_NE(message.find("--" + option), std::string::npos) << message;
    }
    if (!before.empty()) {
      EXPECT_EQ(config.get(option), before) << option;
    }
  };
  expectRefused("no-such-option", "1");
  for (const OptionSpec& spec : info().options.specs()) {
    switch (spec.kind) {
      case OptionKind::Flag:
        expectRefused(spec.name, "maybe");
        break;
      case OptionKind::Integer:
        for (const char* text : {"", "abc", "1.5", "64abc", " 1", "+1"}) expectRefused(spec.name, text);
        if (spec.min > INT64_MIN) expectRefused(spec.name, std::to_string(spec.min - 1));
        if (spec.max < INT64_MAX) expectRefused(spec.name, std::to_string(spec.max + 1));
        break;
      case OptionKind::Choice:
        expectRefused(spec.name, "bogus");
        break;
      case OptionKind::Number:
        for (const char* text : {"", "abc", "nan", "NaN", "inf", "-inf", "1e999", "0x1p3", " 1",
                                 "+1", "1.5x", ".", "1e"})
          expectRefused(spec.name, text);
        expectRefused(spec.name, formatNumber(spec.number_min - 1.0 - std::fabs(spec.number_min)));
        expectRefused(spec.name, formatNumber(spec.number_max + 1.0 + std::fabs(spec.number_max)));
        break;
    }
  }
  EXPECT_NO_THROW(config.validate());
}

// Every option reads back as it was set, for every value a choice takes: the stats JSON and
// `penumbra techniques` print what get() returns, so a mismatch would report another run.
TEST_P(TechniqueConformance, OptionsReadBackAsSet) {
  TechniqueConfig config(GetParam());
  for (const OptionSpec& spec : info().options.specs()) {
    std::vector<std::string> values = {config.get(spec.name)};
    if (spec.kind == OptionKind::Choice) values = spec.choices;
    if (spec.kind == OptionKind::Flag) values = {"true", "false"};
    for (const std::string& value : values) {
      config.set(spec.name, value);
      EXPECT_EQ(config.get(spec.name), value) << GetParam() << " --" << spec.name;
    }
  }
  EXPECT_FALSE(config.describe().empty());
}

// Workers own tiles or rows and counters are summed in a fixed order; SIMD kernels and their scalar
// twins do the same float operations (CMakeLists.txt: -ffp-contract=off). Images and counters must
// not depend on either, with the technique's defaults, on every light of two built-in scenes.
TEST_P(TechniqueConformance, ThreadsAndSimdDoNotChangeTheResult) {
  for (const char* name : {"spheres", "multilight"}) {
    const Frame f = makeFrame(builtinScene(name), 96, 64);
    const TechniqueConfig config(GetParam());
    RenderContext one_scalar;
    one_scalar.simd = false;
    LightsResult base;
    {
      ThreadLimit limit(1);
      base = renderAll(config, f, one_scalar);
    }
    for (const bool simd : {false, true}) {
      ThreadLimit limit(2);
      RenderContext context;
      context.simd = simd;
      std::string what;
      EXPECT_TRUE(sameOutput(renderAll(config, f, context), base, what))
          << GetParam() << " " << name << (simd ? " simd" : " scalar") << ": " << what;
    }
  }
}

// A technique that claims soft shadows must give the hard shadow volume's image exactly when
// the light has no radius (README, Conventions); a ray tracer gives the hard oracle,
// which may differ from the volume only on shadow boundaries (ties). A technique whose hard
// limit is itself approximate (PCSS: the plain shadow map) declares how far from the volume it
// stays (TechniqueTraits::zero_radius_mae_bound), and is held to that: the suite had no way to
// say "soft, but not exact at radius 0" short of calling it hard, which would have compared
// its soft images with the one-ray oracle and skipped this test.
TEST_P(TechniqueConformance, ZeroRadiusGivesTheHardShadow) {
  if (!info().traits.soft) GTEST_SKIP() << GetParam() << " claims hard shadows only";
  for (const char* name : {"spheres", "columns", "multilight"}) {
    Scene scene = builtinScene(name);
    for (Light& light : scene.lights) light.radius = 0.0f;
    const Frame f = makeFrame(std::move(scene));
    const LightsResult hard = renderAll(TechniqueConfig("volume"), f);
    const LightsResult soft = renderAll(TechniqueConfig(GetParam()), f);
    for (size_t l = 0; l < hard.lights.size(); ++l) {
      const Image<float>& v = soft.lights[l].visibility;
      if (!info().traits.ray_traced && info().traits.zero_radius_mae_bound > 0.0) {
        double difference = 0.0;
        size_t covered = 0;
        for (size_t i = 0; i < v.size(); ++i) {
          if (!(f.eye.depth.depth[i] > 0.0f)) continue;
          difference += std::fabs(double(v[i]) - double(hard.lights[l].visibility[i]));
          ++covered;
        }
        difference = covered ? difference / double(covered) : 0.0;
        std::printf("[ conform  ] %-12s %-10s radius 0: MAE from the hard volume %.4f (bound "
                    "%.4f)\n",
                    GetParam().c_str(), name, difference, info().traits.zero_radius_mae_bound);
        EXPECT_LE(difference, info().traits.zero_radius_mae_bound)
            << GetParam() << " " << name << " light " << l;
        continue;
      }
      if (!info().traits.ray_traced) {
        EXPECT_TRUE(v == hard.lights[l].visibility) << GetParam() << " " << name << " light " << l;
        continue;
      }
      const BoundaryAgreement a =
          compareHardShadows(v, hard.lights[l].visibility, f.eye.depth.depth);
      EXPECT_EQ(a.off_boundary, 0u) << GetParam() << " " << name << " light " << l;
      EXPECT_LE(a.differingFraction(), 1e-3) << GetParam() << " " << name << " light " << l;
    }
  }
}

// Casters whose volume an eye ray enters many times (hard_casters.h): a comb, one connected
// non-convex mesh whose five teeth's shadows a ray grazing the ground crosses one after another
// (depth complexity 5 within one volume), and a grid of sixteen boxes merged into one mesh
// under a low light (most of the floor in several boxes' shadows). A technique that claims the
// hard volume's image (claimsVolumesImage; the lights here have no radius) must give it at every
// pixel. The built-in scenes' casters are convex or nearly so; if this failed, a technique would
// count one caster's volume right only where a ray enters it once.
TEST_P(TechniqueConformance, HardCastersGiveTheVolumesImage) {
  if (!claimsVolumesImage(info().traits)) GTEST_SKIP() << GetParam() << " does not claim the volume's image";
  const Scene scenes[] = {testing::combOverGround(5), testing::boxGridUnderLowLight()};
  for (const Scene& scene : scenes) {
    const Frame f = makeFrame(scene);
    const LightsResult volume = renderAll(TechniqueConfig("volume"), f);
    const LightsResult r = renderAll(TechniqueConfig(GetParam()), f);
    size_t differing = 0, shadowed = 0;
    for (size_t i = 0; i < volume.lights[0].visibility.size(); ++i) {
      differing += r.lights[0].visibility[i] != volume.lights[0].visibility[i];
      shadowed += volume.lights[0].visibility[i] == 0.0f && f.eye.depth.depth[i] > 0.0f;
    }
    std::printf("[ conform  ] %-12s %-20s %zu pixels differ from volume (%zu shadowed)\n",
                GetParam().c_str(), scene.name.c_str(), differing, shadowed);
    EXPECT_GT(shadowed, size_t(kWidth * kHeight / 20)) << scene.name << ": the scene casts little";
    EXPECT_EQ(differing, 0u) << GetParam() << " " << scene.name;
  }
}

// Error against the oracle on the built-in scenes, within the bounds the technique declares
// (TechniqueTraits): 1024 rays for soft techniques, one ray to the centre for hard ones. A
// technique that claims more accuracy than it has fails here.
TEST_P(TechniqueConformance, WithinItsDeclaredErrorOfTheOracle) {
  const TechniqueTraits& traits = info().traits;
  for (const std::string& name : builtinSceneNames()) {
    const Frame& f = builtinFrame(name);
    const LightsResult& truth = oracle(name, f, traits.soft);
    const OracleError e = oracleError(f, renderAll(TechniqueConfig(GetParam()), f), truth);
    std::printf("[ conform  ] %-12s %-10s MAE covered %.4f (bound %.4f)  penumbra %.4f (bound "
                "%.4f, %zu px)\n",
                GetParam().c_str(), name.c_str(), e.covered, traits.covered_mae_bound, e.penumbra,
                traits.penumbra_mae_bound, e.penumbra_pixels);
    EXPECT_LE(e.covered, traits.covered_mae_bound) << GetParam() << " " << name;
    if (traits.soft) {
      EXPECT_LE(e.penumbra, traits.penumbra_mae_bound) << GetParam() << " " << name;
    }
  }
}

// Hostile but valid geometry: zero-area and repeated-vertex triangles, an edge shared by three
// triangles, coincident duplicate triangles, inconsistent winding, a lone open triangle, the eye
// inside a closed box, the light inside a closed box, and meshes at 1e-4 and 1e4 units. Every
// technique must return a visibility in [0, 1] for every pixel, never crash or throw.
TEST_P(TechniqueConformance, SurvivesDegenerateAndHostileMeshes) {
  struct Case {
    const char* what;
    Scene scene;
  };
  const auto base = [](const char* name, vec3 eye, vec3 target, vec3 light, float radius,
                       float scale) {
    Scene scene;
    scene.name = name;
    const uint32_t material = addMaterial(scene, "grey", vec3(0.7f));
    addMesh(scene, makeGroundPlane(vec3(0.0f), 6.0f * scale), material);
    addLight(scene, light * scale, radius * scale);
    scene.camera.position = eye * scale;
    scene.camera.target = target * scale;
    scene.camera.near_plane = 0.05f * scale;
    return scene;
  };
  const auto soup = [](std::vector<vec3> positions, std::vector<uint32_t> indices) {
    Mesh mesh;
    mesh.name = "soup";
    mesh.positions = std::move(positions);
    mesh.indices = std::move(indices);
    return mesh;
  };
  std::vector<Case> cases;
  const vec3 eye(4.0f, 5.0f, 7.0f), target(0.0f, 0.5f, 0.0f), light(-2.0f, 6.0f, 1.0f);
  {
    Scene s = base("degenerate", eye, target, light, 0.5f, 1.0f);
    // Zero-area (collinear), a repeated vertex, and a proper triangle sharing their vertices.
    addMesh(s,
            soup({vec3(-1, 1, 0), vec3(0, 1, 0), vec3(1, 1, 0), vec3(0, 1.5f, 1)},
                 {0, 1, 2, 0, 0, 3, 0, 2, 3, 1, 1, 1}),
            0);
    cases.push_back({"degenerate triangles", std::move(s)});
  }
  {
    Scene s = base("non-manifold", eye, target, light, 0.5f, 1.0f);
    // Three fins on the edge (0, 1), one of them wound the other way.
    addMesh(s,
            soup({vec3(0, 1, -1), vec3(0, 1, 1), vec3(1, 2, 0), vec3(-1, 2, 0), vec3(0, 0.3f, 0)},
                 {0, 1, 2, 1, 0, 3, 0, 1, 4}),
            0);
    cases.push_back({"edge of three triangles, inconsistent winding", std::move(s)});
  }
  {
    Scene s = base("duplicates", eye, target, light, 0.5f, 1.0f);
    Mesh box = makeBox(vec3(-0.5f, 0.5f, -0.5f), vec3(0.5f, 1.5f, 0.5f));
    const std::vector<uint32_t> once = box.indices;
    box.indices.insert(box.indices.end(), once.begin(), once.end());
    box.corner_normals.clear();
    addMesh(s, std::move(box), 0);
    cases.push_back({"every triangle twice", std::move(s)});
  }
  {
    Scene s = base("lone", eye, target, light, 1.0f, 1.0f);
    addMesh(s, soup({vec3(-1, 1, -1), vec3(1, 1, -1), vec3(0, 1, 1)}, {0, 1, 2}), 0);
    cases.push_back({"one open triangle", std::move(s)});
  }
  {
    Scene s = base("eye in box", vec3(0.2f, 1.0f, 0.3f), vec3(3.0f, 0.0f, 2.0f), light, 0.5f, 1.0f);
    addMesh(s, makeBox(vec3(-1.0f, 0.01f, -1.0f), vec3(1.0f, 2.0f, 1.0f)), 0);
    cases.push_back({"eye inside a closed box", std::move(s)});
  }
  {
    Scene s = base("light in box", eye, target, vec3(0.0f, 1.0f, 0.0f), 0.2f, 1.0f);
    addMesh(s, makeBox(vec3(-0.6f, 0.5f, -0.6f), vec3(0.6f, 1.5f, 0.6f)), 0);
    cases.push_back({"light inside a closed box", std::move(s)});
  }
  for (const float scale : {1e-4f, 1e4f}) {
    Scene s = base(scale < 1.0f ? "tiny" : "huge", eye, target, light, 0.5f, scale);
    addMesh(s, makeSphere(vec3(0.0f, 1.0f, 0.0f) * scale, 0.6f * scale, 12, 6), 0);
    cases.push_back({scale < 1.0f ? "1e-4 units" : "1e4 units", std::move(s)});
  }
  for (Case& c : cases) {
    c.scene.finalize();
    const Frame f = makeFrame(std::move(c.scene), 64, 48);
    LightsResult r;
    ASSERT_NO_THROW(r = renderAll(TechniqueConfig(GetParam()), f)) << c.what;
    ASSERT_EQ(r.lights.size(), f.scene.lights.size());
    for (const TechniqueResult& result : r.lights) {
      ASSERT_EQ(result.visibility.width(), 64) << c.what;
      size_t bad = 0;
      for (size_t i = 0; i < result.visibility.size(); ++i)
        bad += !(result.visibility[i] >= 0.0f && result.visibility[i] <= 1.0f);
      EXPECT_EQ(bad, 0u) << GetParam() << ": " << c.what;
    }
    // A hard technique that claims the volume's image gives it here too (the soft ones' lights
    // have a radius in these scenes).
    if (!info().traits.soft && claimsVolumesImage(info().traits)) {
      const LightsResult volume = renderAll(TechniqueConfig("volume"), f);
      size_t differing = 0;
      for (size_t l = 0; l < volume.lights.size(); ++l)
        for (size_t i = 0; i < volume.lights[l].visibility.size(); ++i)
          differing += r.lights[l].visibility[i] != volume.lights[l].visibility[i];
      EXPECT_EQ(differing, 0u) << GetParam() << ": " << c.what << " differs from volume";
    }
  }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Registered, TechniqueConformance, ::testing::ValuesIn(techniqueNames()),
                         testName);

// The test technique is in the suite by its one registration, and the suite can fail: rendering
// everything lit is far outside the bound an exact technique would declare (the volume's), so
// a technique claiming that bound while lighting everything would fail the error test above.
TEST(TechniqueConformanceSuite, RegisteredTestTechniqueIsRunAndCanFail) {
  ASSERT_TRUE(all_lit_registered);
  const std::vector<std::string> names = techniqueNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "test-all-lit"), names.end());
  const Frame& f = builtinFrame("columns");
  const OracleError e =
      oracleError(f, renderAll(TechniqueConfig("test-all-lit"), f), oracle("columns", f, false));
  EXPECT_GT(e.covered, 10.0 * findTechnique("volume").traits.covered_mae_bound);
  EXPECT_THROW(registerTechnique(allLitTechnique()), Error);  // a name is registered once
}

}  // namespace test_technique_conformance
}  // namespace penumbra
