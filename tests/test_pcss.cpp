// Percentage-closer soft shadows (`pcss`): the penumbra widens with the light's radius and with
// the distance from blocker to receiver (Fernando 2005's estimate, w = R (d_r - d_b) / d_b),
// and radius 0 is the plain shadow map. The conformance suite holds it to its declared error.
#include <gtest/gtest.h>

#include <cstdio>

#include "eye_frame_util.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/pcss_options.h"
#include "shadows/shadow_map_options.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_pcss {

using Frame = testing::EyeFrame;

// A sphere of radius 0.5 at height h over a ground plane, a light at height 6 above it, seen
// from above at 96 x 64.
Frame sphereOverGround(float height, float radius) {
  Scene s;
  s.name = "sphere";
  const uint32_t material = addMaterial(s, "grey", vec3(0.7f));
  addMesh(s, makeGroundPlane(vec3(0.0f), 4.0f), material);
  addMesh(s, makeSphere(vec3(0.0f, height, 0.0f), 0.5f, 24, 12), material);
  addLight(s, vec3(0.3f, 6.0f, 0.2f), radius);
  s.camera.position = vec3(0.0f, 9.0f, 0.01f);
  s.camera.target = vec3(0.0f);
  s.camera.fov_y = 40.0f;
  s.finalize();
  return testing::makeEyeFrame(std::move(s), 96, 64);
}

// Ground pixels strictly between 0 and 1: the penumbra's area in pixels.
size_t penumbraPixels(const Frame& f, const TechniqueConfig& config) {
  const Image<float> v =
      renderShadows(config, f.scene, f.scene.lights[0], f.view, f.eye).visibility;
  size_t n = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const uint32_t id = f.eye.primitive[i];
    if (id == kNoPrimitive || f.scene.locateTriangle(id).first != 0) continue;
    n += v[i] > 0.0f && v[i] < 1.0f;
  }
  return n;
}

// The penumbra's area must grow strictly with the light's radius (0.1, 0.3, 0.6) and with the
// sphere's height above the ground (1, 2, 3.5) at radius 0.3; at radius 0 there is none (the
// plain map gives 0 or 1). If it did not grow with the radius, the light size would not reach
// the blocker search or the filter; with the height, the blocker distance would not.
TEST(Pcss, PenumbraWidensWithRadiusAndBlockerDistance) {
  const TechniqueConfig pcss("pcss");
  size_t previous = 0;
  for (const float radius : {0.1f, 0.3f, 0.6f}) {
    const size_t n = penumbraPixels(sphereOverGround(2.0f, radius), pcss);
    std::printf("[ pcss     ] radius %.1f, height 2: %zu penumbra pixels\n", radius, n);
    EXPECT_GT(n, previous) << "radius " << radius;
    previous = n;
  }
  previous = 0;
  for (const float height : {1.0f, 2.0f, 3.5f}) {
    const size_t n = penumbraPixels(sphereOverGround(height, 0.3f), pcss);
    std::printf("[ pcss     ] radius 0.3, height %.1f: %zu penumbra pixels\n", height, n);
    EXPECT_GT(n, previous) << "height " << height;
    previous = n;
  }
  EXPECT_EQ(penumbraPixels(sphereOverGround(2.0f, 0.0f), pcss), 0u);
}

// At radius 0 the one lookup per point is the plain shadow map's: where a 1 x 1 `shadow-map`
// with the same bias at that reach (half a texel of slope) says 0 or 1, so does PCSS, on every
// pixel. If it differed, PCSS's hard limit would not be the map it is built on.
TEST(Pcss, ZeroRadiusIsThePlainShadowMap) {
  const Frame f = sphereOverGround(2.0f, 0.0f);
  TechniqueConfig plain("shadow-map");
  plain.options<ShadowMapOptions>().pcf_kernel = 1;
  // PCSS's default bias at the projected point (slope bias 1.5 x half a texel) is a 1 x 1
  // kernel's at reach 1 with slope bias 0.75; PCSS has no normal offset by default.
  plain.options<ShadowMapOptions>().slope_bias = 0.5 * PcssOptions{}.slope_bias;
  plain.options<ShadowMapOptions>().normal_offset = PcssOptions{}.normal_offset;
  const Image<float> a =
      renderShadows(TechniqueConfig("pcss"), f.scene, f.scene.lights[0], f.view, f.eye).visibility;
  const Image<float> b = renderShadows(plain, f.scene, f.scene.lights[0], f.view, f.eye).visibility;
  EXPECT_TRUE(a == b);
}

}  // namespace test_pcss
}  // namespace penumbra
