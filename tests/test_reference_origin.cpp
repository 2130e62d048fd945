// Where the oracle's rays start: the depth-buffer point put back on its triangle.
#include <gtest/gtest.h>

#include "eye_frame_util.h"
#include "scene/builtin_scenes.h"
#include "shadows/stages/light_sampling/ray_origin.h"
#include "test_reference_fixture.h"

namespace penumbra {
namespace test_reference_origin {

// The closest point must be the plane projection inside the triangle, the edge point beyond an
// edge and the vertex beyond a corner; otherwise ray origins would land off the surface.
TEST(ReferenceOrigin, ClosestPointOnTriangle) {
  const dvec3 a(0, 0, 0), b(2, 0, 0), c(0, 0, 2);
  const auto near = [](const dvec3& u, const dvec3& v) { return glm::length(u - v) < 1e-12; };
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(0.5, 3.0, 0.5), a, b, c), dvec3(0.5, 0, 0.5)));
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(1.0, -1.0, -0.5), a, b, c), dvec3(1, 0, 0)));
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(1.5, 0.0, 1.5), a, b, c), dvec3(1, 0, 1)));
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(-1.0, 0.2, 5.0), a, b, c), c));
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(-1.0, 0.0, -1.0), a, b, c), a));
  EXPECT_TRUE(near(closestPointOnTriangle(dvec3(3.0, 1.0, -0.1), a, b, c), b));
}

// From above the ground, origins sit a hair above the plane (never below, never a visible
// distance above) whatever the depth buffer's rounding; a triangle id whose triangle is far
// from the point falls back to a step toward the eye. If this failed, rays would start behind
// their surface (acne) or away from the shaded point (shifted shadows).
TEST(ReferenceOrigin, OriginsSitJustAboveTheirTriangle) {
  const Scene scene = reference_test::makeScene(
      {reference_test::horizontalQuad("ground", 0.0f, -4.0f, -4.0f, 4.0f, 4.0f)}, Light{});
  const View view =
      View::lookAt(64, 48, vec3(1.5f, 3.0f, 5.0f), vec3(0.0f), vec3(0, 1, 0), 45.0f, 0.1f);
  const EyeBuffers eye = reference_test::groundEyeBuffers(view, 4.0, 0.0);
  const RayOrigins origins(scene, view);
  EXPECT_EQ(origins.triangleCount(), 2u);
  int checked = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      const float depth = eye.depth.depth.at(x, y);
      if (depth == 0.0f) continue;
      const RayStart start = origins.start(x, y, depth, eye.primitive.at(x, y));
      ASSERT_GT(start.origin.y, 0.0) << x << "," << y;
      // 16 float ulps of (coordinates up to 4 + the triangle's 11.3 edge): under 2e-5; a pixel
      // footprint here is about 0.005.
      ASSERT_LT(start.origin.y, 2e-5) << x << "," << y;
      ASSERT_GT(start.plane_normal.y, 0.0);  // the eye's side
      ASSERT_TRUE(start.intoSurface(dvec3(0.0, -1.0, 0.0)));
      ASSERT_FALSE(start.intoSurface(dvec3(3.0, 0.0, 7.0)));  // in the plane: not behind it
      const dvec3 p = view.unproject(x, y, depth);
      // On the plane the point moves by its snapping error and at most that lift inward.
      ASSERT_LT(std::hypot(start.origin.x - p.x, start.origin.z - p.z), 3e-5);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);

  // Pixel (32, 24) sees the ground near the origin; say it shows a triangle of a mesh far away.
  Scene far_scene = scene;
  far_scene.meshes.push_back(reference_test::horizontalQuad("far", 0.0f, 50, 50, 51, 51));
  const RayOrigins far_origins(far_scene, view);
  const float depth = eye.depth.depth.at(32, 24);
  ASSERT_GT(depth, 0.0f);
  const RayStart start = far_origins.start(32, 24, depth, 2);
  const dvec3 p = view.unproject(32, 24, depth);
  EXPECT_EQ(start.plane_normal, dvec3(0.0));  // no plane: every ray is traced
  const double footprint = glm::length(dvec3(view.eye) - p) * 2.0 /
                           (double(view.projection[1][1]) * view.height);
  EXPECT_NEAR(glm::length(start.origin - p), 0.125 * footprint, 1e-9);
  EXPECT_GT(glm::dot(start.origin - p, dvec3(view.eye) - p), 0.0);
}

// A caller walking a frame's pixels with one OriginTriangle (as the oracle's rows, alias-free's
// samples and exact's tiles do) gets every origin bit for bit as a fresh call would, on a scene
// whose rows cross hundreds of triangles and the background. If this failed, a pixel would be
// given the previous triangle's vertices or normals, or the kept values would differ from the
// fresh ones in their last bits and move the shaded points of every technique.
TEST(ReferenceOrigin, KeptTriangleGivesTheSameOrigins) {
  const testing::EyeFrame f = testing::makeEyeFrame(builtinScene("columns"), 160, 107);
  const RayOrigins origins(f.scene, f.view);
  size_t pixels = 0, differing = 0;
  for (int y = 0; y < f.view.height; ++y) {
    OriginTriangle kept;
    for (int x = 0; x < f.view.width; ++x) {
      const float depth = f.eye.depth.depth.at(x, y);
      if (!(depth > 0.0f)) continue;
      const uint32_t id = f.eye.primitive.at(x, y);
      const RayStart a = origins.start(x, y, depth, id, kept);
      const RayStart b = origins.start(x, y, depth, id);
      ++pixels;
      differing += a.origin != b.origin || a.plane_point != b.plane_point ||
                   a.plane_normal != b.plane_normal;
    }
  }
  EXPECT_GT(pixels, 10000u);
  EXPECT_EQ(differing, 0u);
}

}  // namespace test_reference_origin
}  // namespace penumbra
