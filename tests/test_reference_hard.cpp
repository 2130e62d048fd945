// The oracle's hard shadows (one ray to the light centre) against analytic answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "shadows/reference/reference_technique.h"
#include "test_reference_fixture.h"

namespace penumbra {
namespace test_reference_hard {

using reference_test::box;
using reference_test::coveredPixels;
using reference_test::groundEyeBuffers;
using reference_test::horizontalQuad;
using reference_test::makeScene;
using reference_test::referenceConfig;
using reference_test::renderReference;

constexpr float kGroundHalf = 4.0f;

TechniqueConfig referenceOptions(int rays = 64) { return referenceConfig(rays); }

View obliqueView() {
  return View::lookAt(96, 72, vec3(1.5f, 6.0f, 5.0f), vec3(0.0f), vec3(0, 1, 0), 45.0f, 0.1f);
}

// Screen position in pixels of a world point (y down, as the buffers store rows).
dvec2 toScreen(const View& view, const dvec3& p) {
  const vec4 clip = view.toClip(vec4(vec3(p), 1.0f));
  return dvec2((clip.x / clip.w * 0.5 + 0.5) * view.width,
               (0.5 - clip.y / clip.w * 0.5) * view.height);
}

// A unit square at height 1 over the ground, lit by a point light: the shadow is the square's
// central projection onto the ground, a convex quad on screen. Checked with the eye buffers'
// true triangle ids and with every pixel naming triangle 0, which does not hold half of the
// points (the fallback for eye buffers that disagree with themselves). If this failed, the
// oracle's rays start at the wrong points, aim at the wrong place or miss the occluder.
void checkSquareShadow(uint32_t all_ids) {
  Light light;
  light.center = vec3(0.3f, 4.0f, 0.2f);
  const Scene scene =
      makeScene({horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf,
                                kGroundHalf),
                 horizontalQuad("occluder", 1.0f, -0.5f, -0.5f, 0.5f, 0.5f)},
                light);
  const View view = obliqueView();
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0, all_ids);
  const TechniqueResult result = renderReference(referenceOptions(), scene, light, view, eye);

  // Shadow corners: L + (q - L) * L.y / (L.y - q.y) on y = 0, in counter-clockwise screen order.
  const dvec3 l(light.center);
  std::array<dvec2, 4> corners;
  const double qs[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int i = 0; i < 4; ++i) {
    const dvec3 q(qs[i][0], 1.0, qs[i][1]);
    corners[size_t(i)] = toScreen(view, l + (q - l) * (l.y / (l.y - q.y)));
  }
  // Signed pixel distance to each edge line, positive inside.
  double orientation = 0.0;
  for (int i = 0; i < 4; ++i) {
    const dvec2 a = corners[size_t(i)], b = corners[size_t((i + 1) % 4)];
    orientation += a.x * b.y - b.x * a.y;
  }
  int shadowed = 0, lit = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      if (eye.depth.depth.at(x, y) == 0.0f) {
        EXPECT_EQ(result.visibility.at(x, y), 1.0f) << "background pixel " << x << "," << y;
        continue;
      }
      const dvec2 c(x + 0.5, y + 0.5);
      double inside = 1e30, outside = 0.0;
      for (int i = 0; i < 4; ++i) {
        const dvec2 a = corners[size_t(i)], b = corners[size_t((i + 1) % 4)];
        const dvec2 e = b - a;
        double d = (e.x * (c.y - a.y) - e.y * (c.x - a.x)) / glm::length(e);
        if (orientation < 0) d = -d;
        inside = std::min(inside, d);
        outside = std::max(outside, -d);
      }
      if (inside > 1.0) {
        EXPECT_EQ(result.visibility.at(x, y), 0.0f) << "pixel " << x << "," << y;
        ++shadowed;
      } else if (outside > 1.0) {
        EXPECT_EQ(result.visibility.at(x, y), 1.0f) << "pixel " << x << "," << y;
        ++lit;
      }
    }
  }
  EXPECT_GT(shadowed, 100);  // the shadow is big enough for the test to mean something
  EXPECT_GT(lit, 2000);
  const int covered = coveredPixels(eye);
  EXPECT_EQ(result.stats.z_reads, uint64_t(covered));
  EXPECT_EQ(result.stats.rays, uint64_t(covered));
}

TEST(ReferenceHard, ShadowOfSquareIsItsProjection) { checkSquareShadow(kNoPrimitive); }

TEST(ReferenceHard, ShadowOfSquareWithInconsistentTriangleIds) { checkSquareShadow(0); }

// The contract (shadows/technique.h, TechniqueTraits::soft): radius 0 degenerates to hard shadows
// and must give exactly the hard result; the `hard` option on a large light must ignore its radius.
// Packets and single rays must agree. If this failed, the three paths to one ray per pixel would
// disagree.
TEST(ReferenceHard, PointLightHardFlagAndPacketsAgree) {
  Light point;
  point.center = vec3(-0.4f, 3.0f, 0.5f);
  const Scene scene = makeScene(
      {horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf, kGroundHalf),
       box(vec3(-0.6f, 0.5f, -0.3f), vec3(0.2f, 1.2f, 0.4f))},
      point);
  const View view = obliqueView();
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  const TechniqueResult a = renderReference(referenceOptions(), scene, point, view, eye);

  Light sphere = point;
  sphere.radius = 0.7f;
  TechniqueConfig hard = referenceOptions();
  hard.options<ReferenceOptions>().hard = true;
  const TechniqueResult b = renderReference(hard, scene, sphere, view, eye);
  RenderContext single;
  single.simd = false;
  const TechniqueResult c = renderReference(referenceOptions(), scene, point, view, eye, single);
  EXPECT_TRUE(a.visibility == b.visibility);
  EXPECT_TRUE(a.visibility == c.visibility);
  EXPECT_TRUE(a.stats.sameCounters(b.stats));
  EXPECT_TRUE(a.stats.sameCounters(c.stats));
  int zeros = 0;
  for (size_t i = 0; i < a.visibility.size(); ++i) zeros += a.visibility[i] == 0.0f ? 1 : 0;
  EXPECT_GT(zeros, 50);  // the box does cast a shadow
}

// A light below a one-sided ground: the ground itself blocks every ray. If this failed, rays
// would start on the light's side of the surface (offset along the wrong side of the normal).
TEST(ReferenceHard, LightBelowTheGroundShadowsIt) {
  Light light;
  light.center = vec3(0.5f, -2.0f, 0.0f);
  const Scene scene = makeScene(
      {horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf, kGroundHalf)},
      light);
  const View view = obliqueView();
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  const TechniqueResult result = renderReference(referenceOptions(), scene, light, view, eye);
  int covered = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      if (eye.depth.depth.at(x, y) == 0.0f) continue;
      ++covered;
      ASSERT_EQ(result.visibility.at(x, y), 0.0f) << "pixel " << x << "," << y;
    }
  }
  EXPECT_GT(covered, 1000);
}

// A point light exactly in the ground's plane: the surface is edge-on to it, which shadow
// volumes treat as casting nothing (lit); a hair below the plane, the ground blocks it. If this
// failed, the surface's own side test would use the offset origin or the rounded depth-buffer
// point instead of the triangle's exact plane, and flip on measure-zero configurations.
TEST(ReferenceHard, EdgeOnLightIsDecidedByTheExactPlane) {
  const Scene scene = makeScene(
      {horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf, kGroundHalf)},
      Light{});
  const View view = obliqueView();
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  Light in_plane;
  in_plane.center = vec3(10.0f, 0.0f, 1.0f);
  Light below = in_plane;
  below.center.y = -1e-3f;
  const TechniqueResult lit = renderReference(referenceOptions(), scene, in_plane, view, eye);
  const TechniqueResult dark = renderReference(referenceOptions(), scene, below, view, eye);
  ASSERT_GT(coveredPixels(eye), 1000);
  for (size_t i = 0; i < lit.visibility.size(); ++i) {
    ASSERT_EQ(lit.visibility[i], 1.0f) << "pixel " << i;
    ASSERT_EQ(dark.visibility[i], eye.depth.depth[i] > 0.0f ? 0.0f : 1.0f) << "pixel " << i;
  }
}

// A light inside a closed box: everything outside is in shadow, which is what the rays say.
// If this failed, rays would stop short of the box or pass through closed geometry.
TEST(ReferenceHard, LightInsideClosedMeshShadowsEverythingOutside) {
  Light light;
  light.center = vec3(0.0f, 2.0f, 0.0f);
  const Scene scene = makeScene(
      {horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf, kGroundHalf),
       box(vec3(-1.0f, 1.5f, -1.0f), vec3(1.0f, 2.5f, 1.0f))},
      light);
  const View view = obliqueView();
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  const TechniqueResult result = renderReference(referenceOptions(), scene, light, view, eye);
  for (size_t i = 0; i < result.visibility.size(); ++i) {
    ASSERT_EQ(result.visibility[i], eye.depth.depth[i] > 0.0f ? 0.0f : 1.0f) << "pixel " << i;
  }
}

// Settings a caller can get wrong are reported, not crashed on or silently clamped.
TEST(ReferenceHard, RejectsBadInputs) {
  Light light;
  const Scene scene = makeScene(
      {horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf, kGroundHalf)},
      light);
  const View view = View::lookAt(16, 12, vec3(0, 5, 5), vec3(0.0f), vec3(0, 1, 0), 45.0f, 0.1f);
  const EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  for (int rays : {0, -1, 4097, 100000}) {
    EXPECT_THROW(renderReference(referenceOptions(rays), scene, light, view, eye), Error)
        << rays << " rays";
  }
  EXPECT_NO_THROW(renderReference(referenceOptions(1), scene, light, view, eye));
  EXPECT_NO_THROW(renderReference(referenceOptions(4096), scene, light, view, eye));

  EyeBuffers bad_id = eye;
  bad_id.primitive.at(3, 3) = 2;  // the scene has 2 triangles: ids 0 and 1
  EXPECT_THROW(renderReference(referenceOptions(), scene, light, view, bad_id), Error);

  const View other = View::lookAt(17, 12, vec3(0, 5, 5), vec3(0.0f), vec3(0, 1, 0), 45.0f, 0.1f);
  EXPECT_THROW(renderReference(referenceOptions(), scene, light, other, eye), Error);

  Light negative = light;
  negative.radius = -1.0f;
  EXPECT_THROW(renderReference(referenceOptions(), scene, negative, view, eye), Error);

  Scene broken = scene;
  broken.meshes[0].indices[4] = 99;
  EXPECT_THROW(renderReference(referenceOptions(), broken, light, view, eye), Error);
  Scene not_finite = scene;
  not_finite.meshes[0].positions[1].x = NAN;
  EXPECT_THROW(renderReference(referenceOptions(), not_finite, light, view, eye), Error);
}

// Nothing to cast shadows, and eye buffers without triangle ids (the ray offset then steps
// toward the eye): every covered pixel is lit. If this failed, an empty BVH or a missing
// surface normal would break the oracle instead of giving the trivial answer.
TEST(ReferenceHard, EmptySceneIsLit) {
  Light light;
  light.radius = 0.5f;
  Scene scene;
  scene.lights.push_back(light);
  const View view = View::lookAt(16, 12, vec3(0, 5, 5), vec3(0.0f), vec3(0, 1, 0), 45.0f, 0.1f);
  EyeBuffers eye = groundEyeBuffers(view, kGroundHalf, 0.0);
  eye.primitive = Image<uint32_t>();
  const TechniqueResult result = renderReference(referenceOptions(), scene, light, view, eye);
  for (size_t i = 0; i < result.visibility.size(); ++i) EXPECT_EQ(result.visibility[i], 1.0f);
  EXPECT_EQ(result.stats.rays, uint64_t(coveredPixels(eye)) * 64u);
}

}  // namespace test_reference_hard
}  // namespace penumbra
