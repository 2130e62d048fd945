// The shadow map's spot frustum (--projection, --spot-fov) and its stencil-limited lookups
// (--stencil-limit: Arvo & Aila 2003, the thesis's publication P4, section 4.2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "eye_frame_util.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/shadow_map_options.h"
#include "shadows/stages/light_depth_maps/light_frustum.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_shadow_map_spot {

using Frame = testing::EyeFrame;

// The spotlight angle whose footprint on the floor 2 below the light is |x|, |z| <= 1.
const double kSpotFov = 2.0 * std::atan(0.5) * 180.0 / 3.14159265358979323846;

// A floor far larger than the view (half size 100), the eye 8 above the origin looking straight
// down with a 90-degree field of view on 64 x 64 pixels: pixel column x shows the floor's
// x in [-8 + x / 4, -8 + (x + 1) / 4), and row y likewise its z. The light is 2 above the
// origin; with `box`, a small box lies on the floor under it.
Frame floorUnderLight(bool box) {
  Scene s;
  s.name = "local light";
  const uint32_t material = addMaterial(s, "grey", vec3(0.7f));
  addMesh(s, makeGroundPlane(vec3(0.0f), 100.0f), material);
  if (box) addMesh(s, makeBox(vec3(-0.3f, 0.0f, -0.2f), vec3(0.2f, 0.6f, 0.4f)), material);
  addLight(s, vec3(0.0f, 2.0f, 0.0f), 0.0f);
  s.camera.position = vec3(0.0f, 8.0f, 0.0f);
  s.camera.target = vec3(0.0f);
  s.camera.up = vec3(0.0f, 0.0f, -1.0f);
  s.camera.fov_y = 90.0f;
  s.finalize();
  return testing::makeEyeFrame(std::move(s), 64, 64);
}

TechniqueConfig spotlight(double fov, bool limit) {
  TechniqueConfig config("shadow-map");
  config.options<ShadowMapOptions>().spot_fov = fov;
  config.options<ShadowMapOptions>().stencil_limit = limit;
  return config;
}

TechniqueResult render(const TechniqueConfig& config, const Frame& f) {
  return renderShadows(config, f.scene, f.scene.lights[0], f.view, f.eye);
}

// The spotlight's footprint |x|, |z| <= 1 holds the pixel centres of columns and rows 28..35
// (centres at -8 + (x + 0.5) / 4, the nearest 1/8 inside the edge): 8 x 8 = 64 of the 4096
// floor pixels are looked up and lit, the other 4032 skipped by the stencil and dark. If the
// counter were off, the frustum volume would be drawn wrongly (a sign, a face, the margin) or
// the counting would not be per pixel; if the image were, the limit would skip lit pixels.
TEST(ShadowMapSpot, StencilLimitSavesExactlyThePixelsOutsideTheFrustum) {
  const Frame f = floorUnderLight(false);
  const TechniqueResult r = render(spotlight(kSpotFov, true), f);
  EXPECT_EQ(r.stats.counter("shadow_map_lookups"), 64u);
  EXPECT_EQ(r.stats.counter("lookups_saved"), 4096u - 64u);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool inside = x >= 28 && x <= 35 && y >= 28 && y <= 35;
      ASSERT_EQ(r.visibility.at(x, y), inside ? 1.0f : 0.0f) << x << ", " << y;
    }
  }
  // Without the limit every floor pixel is looked up and none saved.
  const TechniqueResult all = render(spotlight(kSpotFov, false), f);
  EXPECT_EQ(all.stats.counter("shadow_map_lookups"), 4096u);
  EXPECT_EQ(all.stats.counter("lookups_saved"), 0u);
}

// Limited and unlimited lookups give the same image, bit for bit, with an occluder in the spot,
// from above (the eye outside the frustum) and from a point inside it looking sideways (the
// frustum's stencil is counted z-fail, so the eye inside it changes nothing), with wide and
// narrow spots. If they differed, the stencil would skip points the lookup finds inside.
TEST(ShadowMapSpot, StencilLimitedImageEqualsUnlimited) {
  for (const bool eye_inside : {false, true}) {
    Scene s = floorUnderLight(true).scene;
    if (eye_inside) {
      s.camera.position = vec3(0.4f, 0.8f, 0.5f);
      s.camera.target = vec3(-3.0f, 0.0f, -2.0f);
      s.camera.up = vec3(0.0f, 1.0f, 0.0f);
    }
    const Frame f = testing::makeEyeFrame(std::move(s), 96, 64);
    for (const double fov : {30.0, kSpotFov, 120.0}) {
      const TechniqueResult limited = render(spotlight(fov, true), f);
      const TechniqueResult unlimited = render(spotlight(fov, false), f);
      EXPECT_TRUE(limited.visibility == unlimited.visibility)
          << (eye_inside ? "eye inside" : "eye above") << ", fov " << fov;
      EXPECT_GT(limited.stats.counter("lookups_saved"), 0u) << fov;
      EXPECT_EQ(limited.stats.counter("lookups_saved") +
                    limited.stats.counter("shadow_map_lookups"),
                unlimited.stats.counter("shadow_map_lookups"));
    }
  }
}

// Auto picks one frustum fitted around the visible points when the light is outside their box
// (a 2.4 x 2.4 floor with a box, seen from above, the light 3.5 above it), and a
// cube when the light is among them; a forced spot with the light among them is refused with a
// message. If the spot were chosen wrongly, visible points would fall outside the map.
TEST(ShadowMapSpot, AutoFitsASpotOnlyWhenTheLightIsOutsideTheVisiblePoints) {
  Scene s = floorUnderLight(true).scene;
  s.meshes[0] = makeGroundPlane(vec3(0.0f), 1.2f);
  s.meshes[1] = makeBox(vec3(-0.3f, 0.0f, -0.2f), vec3(0.2f, 1.2f, 0.4f));
  s.lights[0].center = vec3(0.4f, 3.5f, 0.2f);
  s.camera.position = vec3(0.0f, 4.0f, 0.0f);
  s.finalize();
  const Frame f = testing::makeEyeFrame(std::move(s), 192, 128);
  const LightFrustums spot =
      chooseLightFrustums(f.scene, f.scene.lights[0], f.view, f.eye, ShadowMapProjection::Auto, 0);
  ASSERT_EQ(spot.faces.size(), 1u);
  EXPECT_FALSE(spot.spotlight);
  EXPECT_LT(spot.faces[0].tan_half, 1.0);
  Light among = f.scene.lights[0];
  among.center = vec3(0.5f, 0.3f, 0.5f);
  EXPECT_EQ(chooseLightFrustums(f.scene, among, f.view, f.eye, ShadowMapProjection::Auto, 0)
                .faces.size(),
            6u);
  EXPECT_THROW(
      chooseLightFrustums(f.scene, among, f.view, f.eye, ShadowMapProjection::Spot, 0), Error);
  // The fitted spot and the cube agree away from shadow boundaries: the box's shadow is there.
  TechniqueConfig cube("shadow-map");
  cube.options<ShadowMapOptions>().projection = ShadowMapProjection::Cube;
  const Image<float> a = render(TechniqueConfig("shadow-map"), f).visibility;
  const Image<float> b = render(cube, f).visibility;
  size_t dark = 0, disagree = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    dark += a[i] == 0.0f;
    disagree += std::fabs(a[i] - b[i]) > 0.5f;
  }
  EXPECT_GT(dark, 40u);
  EXPECT_LT(disagree, dark / 5);
  std::printf("[ spot     ] %zu dark pixels, %zu differ from the cube's\n", dark, disagree);
}

// Inconsistent options are refused by validate() with the option named: an even PCF kernel,
// a spotlight or a stencil limit with a cube.
TEST(ShadowMapSpot, InconsistentOptionsAreRefused) {
  const auto refused = [](const char* option, const char* value, const char* other,
                          const char* other_value) {
    TechniqueConfig config("shadow-map");
    config.set(option, value);
    if (other) config.set(other, other_value);
    try {
      config.validate();
      ADD_FAILURE() << option << " " << value << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("--") + option), std::string::npos)
          << e.what();
    }
  };
  refused("pcf-kernel", "4", nullptr, nullptr);
  refused("spot-fov", "40", "projection", "cube");
  refused("stencil-limit", "true", "projection", "cube");
  TechniqueConfig fine("shadow-map");
  fine.set("spot-fov", "40");
  fine.set("stencil-limit", "true");
  EXPECT_NO_THROW(fine.validate());
}

}  // namespace test_shadow_map_spot
}  // namespace penumbra
