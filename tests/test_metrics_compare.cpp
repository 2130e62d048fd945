#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "metrics/image_compare.h"

namespace penumbra {
namespace test_metrics_compare {

// Errors 0, 0.1, 0.2, 0.5: MAE 0.2, RMSE sqrt(0.3 / 4), max 0.5; with tolerance 0.15, two of
// four pixels are off. Wrong averaging, a missing square root or >= instead of > would show.
TEST(MetricsCompare, KnownValuesGray) {
  Image<float> a(2, 2, 0.5f);
  Image<float> b(2, 2);
  b[0] = 0.5f;
  b[1] = 0.6f;
  b[2] = 0.3f;
  b[3] = 1.0f;
  const ImageDifference d = compareImages(a, b, 0.15);
  EXPECT_EQ(d.pixels, 4u);
  EXPECT_NEAR(d.mae, 0.2, 1e-7);
  EXPECT_NEAR(d.rmse, std::sqrt((0.01 + 0.04 + 0.25) / 4.0), 1e-7);
  EXPECT_NEAR(d.max_error, 0.5, 1e-7);
  EXPECT_EQ(d.count_over_tolerance, 2u);
  EXPECT_DOUBLE_EQ(d.fraction_over_tolerance, 0.5);
  EXPECT_EQ(d.count_nonfinite, 0u);
  // Exactly at the tolerance is not over it.
  EXPECT_EQ(compareImages(a, b, 0.5).count_over_tolerance, 0u);
}

TEST(MetricsCompare, IdenticalImagesHaveNoError) {
  Image<float> a(5, 3, 0.25f);
  const ImageDifference d = compareImages(a, a, 0.0);
  EXPECT_EQ(d.pixels, 15u);
  EXPECT_EQ(d.mae, 0.0);
  EXPECT_EQ(d.rmse, 0.0);
  EXPECT_EQ(d.max_error, 0.0);
  EXPECT_EQ(d.count_over_tolerance, 0u);
}

// The mask restricts every statistic to the chosen pixels (e.g. non-background ones).
TEST(MetricsCompare, MaskSelectsPixels) {
  Image<float> a(3, 1, 0.0f);
  Image<float> b(3, 1);
  b[0] = 1.0f;
  b[1] = 0.5f;
  b[2] = 0.0f;
  Image<uint8_t> mask(3, 1, 1);
  mask[0] = 0;
  const ImageDifference d = compareImages(a, b, 0.1, &mask);
  EXPECT_EQ(d.pixels, 2u);
  EXPECT_DOUBLE_EQ(d.mae, 0.25);
  EXPECT_DOUBLE_EQ(d.max_error, 0.5);
  EXPECT_EQ(d.count_over_tolerance, 1u);
  EXPECT_DOUBLE_EQ(d.fraction_over_tolerance, 0.5);
}

// RGB: a pixel's error is its largest channel difference.
TEST(MetricsCompare, RgbUsesLargestChannel) {
  Image<vec3> a(2, 1, vec3(0.0f));
  Image<vec3> b(2, 1, vec3(0.0f));
  b[0] = vec3(0.1f, -0.3f, 0.2f);
  const ImageDifference d = compareImages(a, b, 0.25);
  EXPECT_NEAR(d.max_error, 0.3, 1e-6);
  EXPECT_NEAR(d.mae, 0.15, 1e-6);
  EXPECT_EQ(d.count_over_tolerance, 1u);
}

// A NaN in a visibility buffer is a bug that must show up, not vanish into an average.
TEST(MetricsCompare, NonFiniteIsCountedNotAveraged) {
  Image<float> a(2, 1, 0.0f);
  Image<float> b(2, 1, 0.0f);
  b[0] = NAN;
  b[1] = 0.5f;
  const ImageDifference d = compareImages(a, b, 0.9);
  EXPECT_EQ(d.count_nonfinite, 1u);
  EXPECT_EQ(d.count_over_tolerance, 1u);
  EXPECT_TRUE(std::isinf(d.max_error));
  EXPECT_DOUBLE_EQ(d.mae, 0.5);
}

TEST(MetricsCompare, RejectsMismatchedInputs) {
  EXPECT_THROW(compareImages(Image<float>(2, 2), Image<float>(2, 3), 0.1), Error);
  EXPECT_THROW(compareImages(Image<float>(2, 2), Image<float>(2, 2), -0.1), Error);
  EXPECT_THROW(compareImages(Image<float>(2, 2), Image<float>(2, 2), NAN), Error);
  Image<uint8_t> mask(1, 1);
  EXPECT_THROW(compareImages(Image<float>(2, 2), Image<float>(2, 2), 0.1, &mask), Error);
}

// Exact comparison counts every pixel that differs at all, however little, and reports the
// largest difference. If it failed, a culling mode that changed one pixel by one LI unit
// (1/255) or by one ulp would pass the sweep's "culling changes no pixel" check, or its
// pixels_differing / max_diff columns would be wrong.
TEST(MetricsCompare, ExactCountsEveryDifferingPixel) {
  Image<float> a(4, 1, 0.5f);
  Image<float> b = a;
  b[1] = std::nextafter(0.5f, 1.0f);  // one ulp: under any tolerance, still a difference
  b[2] = 0.5f - 1.0f / 255.0f;
  b[3] = 0.25f;
  const ExactDifference d = compareExact(a, b);
  EXPECT_EQ(d.pixels, 4u);
  EXPECT_EQ(d.differing, 3u);
  EXPECT_EQ(d.max_error, 0.25);
  // Identical buffers: nothing differs, and the largest difference is 0.
  const ExactDifference same = compareExact(a, a);
  EXPECT_EQ(same.differing, 0u);
  EXPECT_EQ(same.max_error, 0.0);
  // The difference is taken in double: 1 - 1e-8 computed in float would round to 1.
  const Image<float> one(1, 1, 1.0f);
  const Image<float> tiny(1, 1, 1e-8f);
  EXPECT_EQ(compareExact(one, tiny).max_error, 1.0 - double(1e-8f));
}

// Values are compared, not bit patterns: -0 equals +0. A NaN differs even from a NaN, and makes
// the largest difference infinite, so a bug producing NaNs cannot hide as "0 differences".
TEST(MetricsCompare, ExactSignedZeroAndNaN) {
  Image<float> a(3, 1, 0.0f);
  Image<float> b(3, 1, 0.0f);
  b[0] = -0.0f;
  EXPECT_EQ(compareExact(a, b).differing, 0u);
  a[1] = NAN;
  b[1] = NAN;
  const ExactDifference d = compareExact(a, b);
  EXPECT_EQ(d.differing, 1u);
  EXPECT_TRUE(std::isinf(d.max_error));
  EXPECT_THROW(compareExact(Image<float>(2, 2), Image<float>(2, 3)), Error);
}

}  // namespace test_metrics_compare
}  // namespace penumbra
