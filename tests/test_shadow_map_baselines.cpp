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
// darkens by more than 0.1. Leaks: covered pixels the shadow map lights by more than 0.1 above
// the oracle. On the terrain at 160 x 107:
//   slope-scaled bias, no normal offset (before "Bias as engines ship it"): acne 0.65 %;
//   normal offset 1, no ring bias: acne 21 pixels (0.135 %), leaks 1092 pixels (6.82 %);
//   normal offset 0.8, ring bias 4 (the defaults): acne 8 pixels (0.051 %), leaks 1070 (6.68 %).
// The plain map (--pcf-kernel 1) has no acne at all here: what is left is the 3 x 3 kernel's
// off-centre taps reading rough ground that rises towards the light beside the point. A larger
// ring bias removes more (8: 2 pixels, on a facet 2 degrees from edge-on) but lights real
// shadows of casters close above their receiver at low map resolutions (ShadowMap.
// SquareOccluderShadowByHand at 64 texels), so the bound is the 8 measured pixels, and leaks
// may not exceed the 1092 of before. If this failed, the default shadow map would speckle lit
// ground with its own surface again, or buy its freedom from acne with light in the shadows.
TEST(ShadowMapBaselines, ShadowMapAcneAndLeaksOnTheTerrain) {
  const Frame f = testing::makeEyeFrame(terrainScene(), 160, 107);
  const Image<float> truth = oracle(f, true);
  const Image<float> map = visibility(TechniqueConfig("shadow-map"), f);
  const int w = truth.width(), h = truth.height();
  size_t inner = 0, acne = 0, covered = 0, leaks = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (f.eye.depth.depth.at(x, y) == 0.0f) continue;
      ++covered;
      leaks += map.at(x, y) > truth.at(x, y) + 0.1f;
      if (x == 0 || y == 0 || x + 1 == w || y + 1 == h) continue;
      ++inner;
      bool lit_around = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          lit_around = lit_around && truth.at(x + dx, y + dy) == 1.0f;
      if (lit_around && map.at(x, y) < 0.9f) ++acne;
    }
  }
  std::printf("[ baseline ] shadow-map on the terrain: %zu acne pixels of %zu covered (%.3f %%), "
              "%zu leaking pixels of %zu (%.2f %%)\n",
              acne, inner, 100.0 * double(acne) / double(inner), leaks, covered,
              100.0 * double(leaks) / double(covered));
  EXPECT_LE(acne, 8u);
  EXPECT_LE(leaks, 1092u);
}

}  // namespace test_shadow_map_baselines
}  // namespace penumbra
