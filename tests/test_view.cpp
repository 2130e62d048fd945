#include <gtest/gtest.h>

#include "core/error.h"
#include "core/pixel_unprojector.h"
#include "core/view.h"

namespace penumbra {
namespace test_view {

// If the projection or unprojection disagreed, every technique would shade the wrong points.
TEST(View, UnprojectInvertsProjectionAtPixelCentres) {
  const View view = View::lookAt(64, 48, vec3(1, 2, 5), vec3(0, 0.5f, 0), vec3(0, 1, 0), 50, 0.1f);
  const vec3 points[] = {vec3(0, 0, 0), vec3(0.7f, -0.2f, 1.3f), vec3(-2, 1, -3)};
  for (const vec3& p : points) {
    const vec4 clip = view.toClip(vec4(p, 1.0f));
    ASSERT_GT(clip.w, 0.0f);
    const double depth = double(clip.z) / clip.w;
    const double sx = (clip.x / clip.w * 0.5 + 0.5) * view.width;
    const double sy = (0.5 - clip.y / clip.w * 0.5) * view.height;
    const dvec3 back = view.unprojectScreen(sx, sy, depth);
    EXPECT_NEAR(back.x, p.x, 1e-4);
    EXPECT_NEAR(back.y, p.y, 1e-4);
    EXPECT_NEAR(back.z, p.z, 1e-4);
  }
}

// The affine per-pixel ray must give View::unproject's point: off, the coverage technique
// would shade and shadow other points than the depth buffer holds.
TEST(View, PixelUnprojectorMatchesUnproject) {
  const View view =
      View::lookAt(1920, 1080, vec3(30, 12, -40), vec3(0, 0.5f, 0), vec3(0, 1, 0), 50, 0.05f);
  const PixelUnprojector unproject(view);
  for (int y : {0, 1, 539, 1079}) {
    for (int x : {0, 7, 960, 1919}) {
      for (float depth : {1.0f, 0.5f, 1e-3f, 2.5e-6f}) {
        const dvec3 expected = view.unproject(x, y, depth);
        const dvec3 got = unproject(x, y, depth);
        EXPECT_LE(glm::length(got - expected), 1e-12 * glm::length(expected - dvec3(view.eye)))
            << x << " " << y << " " << depth;
      }
    }
  }
}

// Reversed-Z with an infinite far plane: the near plane maps to 1 and directions (w = 0) to 0.
TEST(View, ReversedInfiniteDepth) {
  const View view = View::lookAt(32, 32, vec3(0, 0, 0), vec3(0, 0, -1), vec3(0, 1, 0), 60, 0.5f);
  const vec4 at_near = view.toClip(vec4(0, 0, -0.5f, 1));
  EXPECT_FLOAT_EQ(at_near.z / at_near.w, 1.0f);
  const vec4 at_infinity = view.toClip(vec4(0.1f, 0.2f, -1.0f, 0.0f));
  EXPECT_EQ(at_infinity.z, 0.0f);
  EXPECT_GT(at_infinity.w, 0.0f);
}

TEST(View, RejectsDegenerateCameras) {
  EXPECT_THROW(View::lookAt(0, 10, vec3(0), vec3(0, 0, -1), vec3(0, 1, 0), 45, 0.1f), Error);
  EXPECT_THROW(View::lookAt(10, 10, vec3(0), vec3(0), vec3(0, 1, 0), 45, 0.1f), Error);
  EXPECT_THROW(View::lookAt(10, 10, vec3(0), vec3(0, 1, 0), vec3(0, 1, 0), 45, 0.1f), Error);
  EXPECT_THROW(View::lookAt(10, 10, vec3(NAN), vec3(0, 0, -1), vec3(0, 1, 0), 45, 0.1f), Error);
}

}  // namespace test_view
}  // namespace penumbra
