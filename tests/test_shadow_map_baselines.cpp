// The shadow-map baselines as an engine would tune them (docs/shadow-maps.md, "Bias"), on scenes
// that shadow themselves: the rough terrain under a low light (scenes/failure-modes/) and the
// built-in `fractal`. Against the ray-traced oracle at small sizes, so the suite stays cheap.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "evaluation/fidelity_metrics.h"
#include "eye_frame_util.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "shadows/pcss_options.h"
#include "shadows/reference_options.h"
#include "shadows/shadow_map_options.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_shadow_map_baselines {

using Frame = testing::EyeFrame;

Scene terrainScene() {
  const std::filesystem::path file =
      std::filesystem::path(PENUMBRA_SOURCE_DIR) / "scenes" / "failure-modes" /
      "terrain-low-light.json";
  return loadSceneFile(file.string());
}

Image<float> visibility(const TechniqueConfig& config, const Frame& f) {
  return renderShadows(config, f.scene, f.scene.lights[0], f.view, f.eye).visibility;
}

Image<float> oracle(const Frame& f, bool hard) {
  TechniqueConfig config("reference");
  config.options<ReferenceOptions>().rays = hard ? 1 : 1024;  // the fidelity page's oracle
  config.options<ReferenceOptions>().hard = hard;
  return visibility(config, f);
}

FidelityError errorOf(const TechniqueConfig& config, const Frame& f, const Image<float>& truth,
                      const std::string& label) {
  const FidelityError e = fidelityError({visibility(config, f)}, {truth}, f.eye.depth.depth);
  std::printf("[ baseline ] %s: penumbra MAE %.4f, %.2f %% of covered pixels off by > 0.1\n",
              label.c_str(), e.penumbra.mae, 100.0 * e.fraction_over);
  return e;
}

// PCSS at its defaults against the 1024-ray oracle at 160 x 107, as `penumbra fidelity
// --size 160x107` measures it. Before the defaults of docs/shadow-maps.md ("Bias as engines ship
// it": the receiver's own horizon, slope bias 1.5) it was penumbra MAE 0.0623 and 1.32 % of
// covered pixels off by more than 0.1 on `fractal`, 0.166 and 18.2 % on the terrain. `fractal`
// is held to half of that. The terrain is held to 0.13 and 17 % (0.110 and 15.9 % measured):
// better, but not half, because what is left there is PCSS's own approximation (one averaged
// blocker for ridges at many distances), docs/shadow-maps.md says why. If this failed, PCSS
// would again light grazing facets fully that see only part of the light, or darken lit ground
// with its own surface: a baseline no engine would ship.
TEST(ShadowMapBaselines, PcssErrorOnSelfShadowingScenes) {
  struct Case {
    const char* name;
    Scene scene;
    double penumbra_mae, fraction_over;
  };
  std::vector<Case> cases;
  cases.push_back({"fractal", builtinScene("fractal"), 0.0623 / 2, 0.0132 / 2});
  cases.push_back({"terrain-low-light", terrainScene(), 0.13, 0.17});
  for (Case& c : cases) {
    const Frame f = testing::makeEyeFrame(std::move(c.scene), 160, 107);
    const FidelityError e =
        errorOf(TechniqueConfig("pcss"), f, oracle(f, false), std::string("pcss on ") + c.name);
    EXPECT_LE(e.penumbra.mae, c.penumbra_mae) << c.name;
    EXPECT_LE(e.fraction_over, c.fraction_over) << c.name;
  }
}

// Acne: covered pixels the hard oracle lights, whose 8 neighbours it lights too (so no shadow
// boundary passes within a pixel, where a shadow map may be off by a texel), that the shadow map
// darkens by more than 0.1. On the terrain at 160 x 107 with the defaults of before (constant
// and slope-scaled depth bias, no normal offset): 0.65 % of covered pixels; with the normal
// offset 0.13 %, what is left sits on facets almost edge-on to the light. The bound is 0.25 %.
// If this failed, the default shadow map would speckle lit ground with its own surface again.
TEST(ShadowMapBaselines, ShadowMapAcneOnTheTerrain) {
  const Frame f = testing::makeEyeFrame(terrainScene(), 160, 107);
  const Image<float> truth = oracle(f, true);
  const Image<float> map = visibility(TechniqueConfig("shadow-map"), f);
  const int w = truth.width(), h = truth.height();
  size_t covered = 0, acne = 0;
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      if (f.eye.depth.depth.at(x, y) == 0.0f) continue;
      ++covered;
      bool lit_around = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) lit_around = lit_around && truth.at(x + dx, y + dy) == 1.0f;
      if (lit_around && map.at(x, y) < 0.9f) ++acne;
    }
  }
  const double share = double(acne) / double(covered);
  std::printf("[ baseline ] shadow-map on the terrain: %zu acne pixels of %zu covered (%.3f %%)\n",
              acne, covered, 100.0 * share);
  EXPECT_LE(share, 0.0025);
}

}  // namespace test_shadow_map_baselines
}  // namespace penumbra
