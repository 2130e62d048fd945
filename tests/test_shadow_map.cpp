// The standard shadow map (`shadow-map`): error against the one-ray oracle falls with the
// resolution, a hand-checkable occluder, percentage-closer filtering, and the bias against acne.
// The conformance suite (test_technique_conformance.cpp) runs it through the shared contract.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "eye_frame_util.h"
#include "metrics/shadow_boundary.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/shadow_map_options.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_shadow_map {

using Frame = testing::EyeFrame;

Frame makeFrame(Scene scene, int width, int height) {
  return testing::makeEyeFrame(std::move(scene), width, height);
}

TechniqueConfig shadowMap(int resolution, int kernel) {
  TechniqueConfig config("shadow-map");
  config.options<ShadowMapOptions>().resolution = resolution;
  config.options<ShadowMapOptions>().pcf_kernel = kernel;
  return config;
}

Image<float> visibility(const TechniqueConfig& config, const Frame& f, size_t light = 0) {
  return renderShadows(config, f.scene, f.scene.lights[light], f.view, f.eye).visibility;
}

// A square occluder 1 x 1 at height 1 over a ground plane, a point light 4 above its centre:
// the shadow on the ground is the square scaled by 4 / 3, |x|, |z| < 2/3. Everything scaled by
// `scale` (the technique's near plane must follow the scene's units).
Frame squareOverGround(float scale, vec3 light = vec3(0.0f, 4.0f, 0.0f), int width = 160,
                       int height = 120) {
  Scene s;
  s.name = "square";
  const uint32_t material = addMaterial(s, "grey", vec3(0.7f));
  addMesh(s, makeGroundPlane(vec3(0.0f), 3.0f * scale), material);
  addMesh(s, makeBox(vec3(-0.5f, 1.0f, -0.5f) * scale, vec3(0.5f, 1.05f, 0.5f) * scale), material);
  addLight(s, light * scale, 0.0f);
  s.camera.position = vec3(3.0f, 5.0f, 4.0f) * scale;
  s.camera.target = vec3(0.0f, 0.0f, 0.0f);
  s.camera.near_plane = 0.05f * scale;
  s.finalize();
  return makeFrame(std::move(s), width, height);
}

// Ground pixels (mesh 0) of the frame, with their world position divided by `scale`.
template <class Fn>
void forGroundPixels(const Frame& f, float scale, Fn&& fn) {
  for (int y = 0; y < f.view.height; ++y) {
    for (int x = 0; x < f.view.width; ++x) {
      const uint32_t id = f.eye.primitive.at(x, y);
      if (id == kNoPrimitive || f.scene.locateTriangle(id).first != 0) continue;
      fn(x, y, f.view.unproject(x, y, f.eye.depth.depth.at(x, y)) / double(scale));
    }
  }
}

// The square's shadow on the ground, centred at `centre` (world units / scale): pixels well
// inside it (|x|, |z| < 0.35 from the centre) must be 0, pixels well outside (> 1.0) 1.
struct SquareShadowCheck {
  size_t inside = 0, outside = 0, wrong = 0;
};
SquareShadowCheck checkSquareShadow(const Frame& f, float scale, const Image<float>& v,
                                    const dvec3& centre = dvec3(0.0)) {
  SquareShadowCheck check;
  forGroundPixels(f, scale, [&](int x, int y, const dvec3& p) {
    const dvec3 q = p - centre;
    const double r = std::max(std::fabs(q.x), std::fabs(q.z));
    if (r < 0.35) {
      ++check.inside;
      check.wrong += v.at(x, y) != 0.0f;
    } else if (r > 1.0) {
      ++check.outside;
      check.wrong += v.at(x, y) != 1.0f;
    }
  });
  return check;
}

// Error against the oracle's one-ray hard shadow, as the fraction of covered pixels on the other
// side of 0.5, must fall strictly from 128 to 512 to 2048 texels per face and be small at 2048.
// If it did not fall, the map would not be sampled where the points project (wrong face, wrong
// texel, a resolution that is not used), or the bias would grow with the resolution.
TEST(ShadowMap, ErrorFallsAsResolutionRises) {
  for (const char* name : {"spheres", "columns"}) {
    const Frame f = makeFrame(builtinScene(name), 320, 214);
    TechniqueConfig oracle("reference");
    oracle.options<ReferenceOptions>().hard = true;
    oracle.options<ReferenceOptions>().rays = 1;
    double previous = 1.0;
    for (const int resolution : {128, 512, 2048}) {
      BoundaryAgreement total;
      for (size_t l = 0; l < f.scene.lights.size(); ++l) {
        const BoundaryAgreement a = compareHardShadows(visibility(shadowMap(resolution, 1), f, l),
                                                       visibility(oracle, f, l),
                                                       f.eye.depth.depth);
        total.covered += a.covered;
        total.differing += a.differing;
        total.off_boundary += a.off_boundary;
      }
      const double error = total.differingFraction();
      std::printf("[ smap     ] %-8s %4d texels: %.4f %% of covered pixels differ (%llu of %llu, "
                  "%llu off boundaries)\n",
                  name, resolution, 100.0 * error, (unsigned long long)total.differing,
                  (unsigned long long)total.covered, (unsigned long long)total.off_boundary);
      EXPECT_LT(error, previous) << name << " at " << resolution;
      previous = error;
    }
    EXPECT_LT(previous, 0.005) << name << " at 2048";
  }
}

// The square's shadow by hand: a ground point well inside |x|, |z| < 2/3 is 0, one well outside
// is 1, at every resolution from 64 up and with a plain map as with PCF, at 1e-4, 1 and 1e4
// units. If it failed, the cube face, the projection or the depth comparison would be wrong, or
// the near plane would not follow the scene's scale.
TEST(ShadowMap, SquareOccluderShadowByHand) {
  for (const float scale : {1e-4f, 1.0f, 1e4f}) {
    const Frame f = squareOverGround(scale);
    for (const int resolution : {64, 256, 1024}) {
      for (const int kernel : {1, 3}) {
        const SquareShadowCheck c =
            checkSquareShadow(f, scale, visibility(shadowMap(resolution, kernel), f));
        EXPECT_GT(c.inside, 50u);
        EXPECT_GT(c.outside, 1000u);
        EXPECT_EQ(c.wrong, 0u) << "scale " << scale << ", " << resolution << " texels, pcf "
                             << kernel;
      }
    }
  }
}

// A light far from a small scene (a sun), slanted: the square's shadow, shifted by the slant,
// is still drawn with the light 5.4e3 and 1.6e4 units from a scene 6 units wide. If it failed,
// the light's frustum would be aimed by float arithmetic at the light's distance (lookAt with a
// target one unit away from the light was off by more than the fitted spot's width, and the map
// held nothing) or the map's vertices transformed with too little precision for their texels.
TEST(ShadowMap, DistantLightKeepsItsShadow) {
  const vec3 direction(3.0f, 4.0f, 2.0f);
  // Far away, the square (heights 1 to 1.05) falls shifted by -height x (x, z) / y of the light.
  const dvec3 shift = -1.025 * dvec3(direction.x, 0.0, direction.z) / double(direction.y);
  for (const float distance : {1e3f, 3e3f}) {
    const Frame f = squareOverGround(1.0f, direction * distance);
    for (const int kernel : {1, 3}) {
      const SquareShadowCheck c =
          checkSquareShadow(f, 1.0f, visibility(shadowMap(1024, kernel), f), shift);
      EXPECT_GT(c.inside, 20u);  // the box hides part of its shifted shadow from the camera
      EXPECT_GT(c.outside, 1000u);
      EXPECT_EQ(c.wrong, 0u) << "light " << glm::length(direction) * distance
                           << " units away, pcf " << kernel;
    }
  }
}

// Percentage-closer filtering gives fractions: with a 5 x 5 kernel some pixels along the
// square's shadow boundary lie strictly between 0 and 1; a plain map (1 x 1) gives only 0 or 1.
// If it failed, the kernel would not be applied, or the plain map would average something.
TEST(ShadowMap, PcfSoftensTheBoundary) {
  const Frame f = squareOverGround(1.0f);
  const auto fractional = [&](int kernel) {
    const Image<float> v = visibility(shadowMap(256, kernel), f);
    size_t n = 0;
    for (size_t i = 0; i < v.size(); ++i) n += v[i] > 0.0f && v[i] < 1.0f;
    return n;
  };
  EXPECT_GT(fractional(5), 20u);
  EXPECT_EQ(fractional(1), 0u);
}

// A plane lit at a grazing angle (the light 1 above the ground and 8 to the side, about 7
// degrees above the horizon, nothing else in the scene): without bias the map's own samples of
// the plane shadow it (acne), with the default bias every ground pixel is lit. If the first
// failed the test would not be grazing enough to show anything; if the second, the default
// bias would not cover the slope.
TEST(ShadowMap, DefaultBiasAvoidsAcneAtGrazingAngles) {
  Scene s;
  s.name = "grazing";
  const uint32_t material = addMaterial(s, "grey", vec3(0.7f));
  addMesh(s, makeGroundPlane(vec3(0.0f), 3.0f), material);
  addLight(s, vec3(-8.0f, 1.0f, 0.5f), 0.0f);
  s.camera.position = vec3(3.0f, 4.0f, 5.0f);
  s.camera.target = vec3(0.0f);
  s.finalize();
  const Frame f = makeFrame(std::move(s), 160, 120);
  const auto shadowedFraction = [&](const TechniqueConfig& config) {
    const Image<float> v = visibility(config, f);
    size_t ground = 0, shadowed = 0;
    forGroundPixels(f, 1.0f, [&](int x, int y, const dvec3&) {
      ++ground;
      shadowed += v.at(x, y) < 1.0f;
    });
    EXPECT_GT(ground, 5000u);
    return double(shadowed) / double(ground);
  };
  for (const int resolution : {256, 1024}) {
    TechniqueConfig no_bias = shadowMap(resolution, 3);
    no_bias.options<ShadowMapOptions>().constant_bias = 0.0;
    no_bias.options<ShadowMapOptions>().slope_bias = 0.0;
    no_bias.options<ShadowMapOptions>().normal_offset = 0.0;
    no_bias.options<ShadowMapOptions>().ring_bias = 0.0;
    EXPECT_GT(shadowedFraction(no_bias), 0.2) << resolution << " texels, no bias";
    EXPECT_EQ(shadowedFraction(shadowMap(resolution, 3)), 0.0) << resolution << " texels";
  }
}

// Number options read strictly: what the command line takes for the biases.
TEST(ShadowMap, BiasOptionsParseAsNumbers) {
  TechniqueConfig config("shadow-map");
  config.set("constant-bias", "0.25");
  config.set("slope-bias", "2e0");
  config.set("ring-bias", "3");
  EXPECT_EQ(config.options<ShadowMapOptions>().ring_bias, 3.0);
  EXPECT_EQ(config.options<ShadowMapOptions>().constant_bias, 0.25);
  EXPECT_EQ(config.options<ShadowMapOptions>().slope_bias, 2.0);
  EXPECT_EQ(config.get("constant-bias"), "0.25");
  EXPECT_THROW(config.set("slope-bias", "-1"), Error);
  EXPECT_THROW(config.set("slope-bias", "1,5"), Error);
  EXPECT_EQ(config.options<ShadowMapOptions>().slope_bias, 2.0);
}

}  // namespace test_shadow_map
}  // namespace penumbra
