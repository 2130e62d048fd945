#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "metrics/heatmap.h"

namespace penumbra {
namespace test_metrics_heatmap {

int brightness(const glm::u8vec3& c) { return int(c.x) + int(c.y) + int(c.z); }

// Identical inputs must give a completely black map: any colour would suggest an error.
TEST(MetricsHeatmap, IdenticalInputsAreBlack) {
  Image<float> a(4, 3);
  for (size_t i = 0; i < a.size(); ++i) a[i] = float(i) / 12.0f;
  const Image<glm::u8vec3> heat = diffHeatmap(a, a, 0.1f);
  ASSERT_EQ(heat.width(), 4);
  ASSERT_EQ(heat.height(), 3);
  for (size_t i = 0; i < heat.size(); ++i) EXPECT_EQ(heat[i], glm::u8vec3(0)) << i;
  const Image<vec3> c(2, 2, vec3(0.3f));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(diffHeatmap(c, c, 1.0f)[i], glm::u8vec3(0));
}

// The colour map must brighten monotonically so larger errors always look worse, and saturate
// at the scale.
TEST(MetricsHeatmap, ColorMapIsMonotonicAndSaturates) {
  int previous = -1;
  for (int i = 0; i <= 100; ++i) {
    const int b = brightness(errorColor(float(i) / 100.0f));
    EXPECT_GE(b, previous) << i;
    previous = b;
  }
  EXPECT_EQ(errorColor(0.0f), glm::u8vec3(0));
  EXPECT_EQ(errorColor(2.0f), errorColor(1.0f));
  EXPECT_EQ(errorColor(-1.0f), errorColor(0.0f));
  EXPECT_EQ(errorColor(NAN), errorColor(1.0f));
  EXPECT_GT(brightness(errorColor(1.0f)), 600);  // inferno ends near pale yellow
}

TEST(MetricsHeatmap, ErrorScalesIntoTheMap) {
  Image<float> a(3, 1, 0.0f);
  Image<float> b(3, 1);
  b[0] = 0.05f;
  b[1] = 0.1f;
  b[2] = NAN;
  const Image<glm::u8vec3> heat = diffHeatmap(a, b, 0.1f);
  EXPECT_EQ(heat[0], errorColor(0.5f));
  EXPECT_EQ(heat[1], errorColor(1.0f));
  EXPECT_EQ(heat[2], errorColor(1.0f));
  EXPECT_THROW(diffHeatmap(a, b, 0.0f), Error);
  EXPECT_THROW(diffHeatmap(a, Image<float>(1, 3), 1.0f), Error);
}

TEST(MetricsHeatmap, VisibilityToImageIsLinearGray) {
  Image<float> v(4, 1);
  v[0] = 0.0f;
  v[1] = 0.5f;
  v[2] = 1.0f;
  v[3] = 2.0f;
  const Image<glm::u8vec3> img = visibilityToImage(v);
  EXPECT_EQ(img[0], glm::u8vec3(0));
  EXPECT_EQ(img[1], glm::u8vec3(128));
  EXPECT_EQ(img[2], glm::u8vec3(255));
  EXPECT_EQ(img[3], glm::u8vec3(255));
}

}  // namespace test_metrics_heatmap
}  // namespace penumbra
