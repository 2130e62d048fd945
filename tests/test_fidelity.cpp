// The fidelity page's numbers (evaluation/fidelity_metrics.h) on hand-made images and a
// synthetic error curve, the strip's layout, and `penumbra fidelity` on a tiny scene.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "core/error.h"
#include "evaluation/fidelity_metrics.h"
#include "evaluation/fidelity_strip.h"
#include "metrics/heatmap.h"

namespace penumbra {
namespace test_fidelity {

Image<float> imageOf(int w, int h, const std::vector<float>& values) {
  Image<float> image(w, h);
  for (size_t i = 0; i < values.size(); ++i) image[i] = values[i];
  return image;
}

// A 4x2 frame: pixel 7 is background (depth 0). The oracle has penumbra (0 < v < 1) at pixels
// 2, 3 and 4 only; 0, 1, 5 and 6 are umbra or lit, 7 is background and never counted.
//   pixel      0    1    2     3     4    5    6    7
//   oracle     0    1    0.5   0.25  0.9  1    0    1
//   technique  0.2  1    0.5   0.5   0.3  0.95 0    0   (7: background, error 1 ignored)
//   |error|    0.2  0    0     0.25  0.6  0.05 0    -
TEST(FidelityMetrics, HandComputedErrorsOverCoveredAndPenumbraPixels) {
  const Image<float> depth = imageOf(4, 2, {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.0f});
  const Image<float> oracle = imageOf(4, 2, {0, 1, 0.5f, 0.25f, 0.9f, 1, 0, 1});
  const Image<float> technique = imageOf(4, 2, {0.2f, 1, 0.5f, 0.5f, 0.3f, 0.95f, 0, 0});
  const FidelityError e = fidelityError({technique}, {oracle}, depth, 0.1);
  // Covered: 7 pixels, errors {0.2, 0, 0, 0.25, 0.6, 0.05, 0}: sum 1.1, squares 0.4650.
  EXPECT_EQ(e.covered.pixels, 7u);
  EXPECT_NEAR(e.covered.mae, 1.1 / 7.0, 1e-6);
  EXPECT_NEAR(e.covered.rmse, std::sqrt(0.4650 / 7.0), 1e-6);
  EXPECT_NEAR(e.covered.p99, 0.6, 1e-6);  // nearest rank: ceil(0.99 * 7) = 7th of 7
  // Signed: 0.2 + 0.25 - 0.6 - 0.05 = -0.2 (an |error| or a swapped sign would not give it).
  EXPECT_NEAR(e.covered.mean_signed, -0.2 / 7.0, 1e-6);
  // Over 0.1: 0.2, 0.25, 0.6 (0.05 is not): 3 of 7. The background's error 1 would make it 4.
  EXPECT_NEAR(e.fraction_over, 3.0 / 7.0, 1e-12);
  // Penumbra: pixels 2, 3, 4, errors {0, 0.25, 0.6}: a mask counting pixels 0 or 1 (where the
  // oracle is exactly 0 or 1) would change all three numbers.
  EXPECT_EQ(e.penumbra.pixels, 3u);
  EXPECT_NEAR(e.penumbra.mae, 0.85 / 3.0, 1e-6);
  EXPECT_NEAR(e.penumbra.rmse, std::sqrt((0.0625 + 0.36) / 3.0), 1e-6);
  EXPECT_NEAR(e.penumbra.p99, 0.6, 1e-6);
  EXPECT_NEAR(e.penumbra.mean_signed, -0.35 / 3.0, 1e-6);
}

// Two lights pool their pixels (a mean over all, not a mean of the lights' means): light 0 has
// one penumbra pixel off by 0.4, light 1 three penumbra pixels exact. Pooled MAE 0.1; the mean
// of the per-light MAEs would be 0.2.
TEST(FidelityMetrics, LightsArePooledPixelByPixel) {
  const Image<float> depth = imageOf(2, 2, {1, 1, 1, 1});
  const Image<float> oracle0 = imageOf(2, 2, {0.5f, 1, 1, 1});
  const Image<float> tech0 = imageOf(2, 2, {0.9f, 1, 1, 1});
  const Image<float> oracle1 = imageOf(2, 2, {0.5f, 0.5f, 0.5f, 0});
  const FidelityError e = fidelityError({tech0, oracle1}, {oracle0, oracle1}, depth, 0.1);
  EXPECT_EQ(e.penumbra.pixels, 4u);
  EXPECT_NEAR(e.penumbra.mae, 0.1, 1e-6);
  EXPECT_EQ(e.covered.pixels, 8u);
  EXPECT_NEAR(e.covered.mae, 0.05, 1e-6);
  EXPECT_NEAR(e.fraction_over, 1.0 / 8.0, 1e-12);
}

// A NaN visibility is a bug: counted, over the tolerance, and kept out of the means (else the
// page would print "nan" or hide it as 0).
TEST(FidelityMetrics, NonFiniteVisibilityIsCountedNotAveraged) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Image<float> depth = imageOf(2, 1, {1, 1});
  const FidelityError e =
      fidelityError({imageOf(2, 1, {nan, 0.5f})}, {imageOf(2, 1, {0.5f, 0.25f})}, depth, 0.1);
  EXPECT_EQ(e.covered.nonfinite, 1u);
  EXPECT_NEAR(e.covered.mae, 0.25, 1e-6);
  EXPECT_NEAR(e.fraction_over, 1.0, 1e-12);
}

TEST(FidelityMetrics, MismatchedLightsOrSizesAreRefused) {
  const Image<float> a(2, 2, 1.0f), b(3, 2, 1.0f);
  EXPECT_THROW(fidelityError({a}, {a, a}, a), Error);
  EXPECT_THROW(fidelityError({b}, {a}, a), Error);
}

// Nearest rank: of 1..100 the 99th percentile is 99 (an interpolating or off-by-one rank gives
// 99.01 or 100); of one value, that value.
TEST(FidelityMetrics, PercentileIsNearestRank) {
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);
  EXPECT_EQ(percentileOf(v, 0.99), 99.0);
  std::vector<double> one = {0.3};
  EXPECT_EQ(percentileOf(one, 0.99), 0.3);
  std::vector<double> none;
  EXPECT_EQ(percentileOf(none, 0.99), 0.0);
}

// A synthetic oracle whose penumbra error falls as 0.4 / sqrt(N): the search must return the
// smallest N of 1, 2, 4, ... reaching the target, measure each N at most once across targets,
// and say -1 when even the largest N misses.
TEST(FidelityEqualError, SearchFindsSmallestRayCountOnMonotoneCurve) {
  std::vector<int> measured;
  auto measure = [&](int rays) {
    measured.push_back(rays);
    return RayErrorPoint{rays, 0.4 / std::sqrt(double(rays)), 10.0 * rays};
  };
  std::vector<RayErrorPoint> curve;
  // 0.4/sqrt(8) = 0.141 > 0.11 >= 0.4/sqrt(16) = 0.1.
  int at = extendUntilReached(curve, 0.11, 512, measure);
  ASSERT_GE(at, 0);
  EXPECT_EQ(curve[size_t(at)].rays, 16);
  EXPECT_EQ(measured, (std::vector<int>{1, 2, 4, 8, 16}));
  // An easier target is answered from what was measured: no new render.
  at = extendUntilReached(curve, 0.3, 512, measure);
  EXPECT_EQ(curve[size_t(at)].rays, 2);  // 0.4/sqrt(2) = 0.283
  EXPECT_EQ(measured.size(), 5u);
  // A harder one continues at 32, not from 1: 0.4/sqrt(64) = 0.05.
  at = extendUntilReached(curve, 0.05, 512, measure);
  EXPECT_EQ(curve[size_t(at)].rays, 64);
  EXPECT_EQ(measured, (std::vector<int>{1, 2, 4, 8, 16, 32, 64}));
  // Below 0.4/sqrt(512) = 0.0177: not reached; every count up to 512 measured once.
  EXPECT_EQ(extendUntilReached(curve, 0.01, 512, measure), -1);
  EXPECT_EQ(measured.back(), 512);
  EXPECT_EQ(measured.size(), 10u);
}

// With noise the curve can dip below the target early and rise again: the first count reaching
// it is the answer (what a user running N rays would see), not a later or a fitted one.
TEST(FidelityEqualError, FirstCountReachingTargetWinsOnNoisyCurve) {
  const std::vector<RayErrorPoint> curve = {{1, 0.30, 1}, {2, 0.09, 2}, {4, 0.12, 4}, {8, 0.05, 8}};
  EXPECT_EQ(equalErrorIndex(curve, 0.1), 1);
  EXPECT_EQ(equalErrorIndex(curve, 0.06), 3);
  EXPECT_EQ(equalErrorIndex(curve, 0.01), -1);
}

TEST(FidelityEqualError, SearchedCountsArePowersOfTwo) {
  EXPECT_EQ(equalErrorRayCounts(8), (std::vector<int>{1, 2, 4, 8}));
  EXPECT_THROW(equalErrorRayCounts(6), Error);
  EXPECT_THROW(equalErrorRayCounts(0), Error);
}

// The strip is technique | oracle | heat map with 2-pixel gaps, shrunk by a box filter: a wrong
// panel order or a shrink that drops pixels would change these colours.
TEST(FidelityStrip, PanelsSideBySideShrunk) {
  const Image<float> technique(4, 2, 1.0f), oracle(4, 2, 0.0f);
  const Image<glm::u8vec3> strip = fidelityStrip(technique, oracle, 0.5f, 2);
  ASSERT_EQ(strip.width(), 3 * 2 + 2 * 2);
  ASSERT_EQ(strip.height(), 1);
  EXPECT_EQ(strip.at(0, 0), glm::u8vec3(255));  // technique: lit
  EXPECT_EQ(strip.at(2, 0), glm::u8vec3(255));  // gap
  EXPECT_EQ(strip.at(4, 0), glm::u8vec3(0));    // oracle: shadowed
  EXPECT_EQ(strip.at(8, 0), errorColor(1.0f));  // error 1 >= scale 0.5: brightest
  Image<glm::u8vec3> checker(2, 2);
  checker.at(0, 0) = checker.at(1, 1) = glm::u8vec3(200);
  checker.at(1, 0) = checker.at(0, 1) = glm::u8vec3(0);
  EXPECT_EQ(shrinkImage(checker, 2).at(0, 0), glm::u8vec3(100));
}

// `penumbra fidelity` end to end on one tiny scene with two techniques: the page has a row per
// technique with finite numbers, the strips it links exist, and the command is at its top.
class FidelityCli : public testing::CliTest {};

TEST_F(FidelityCli, WritesPageWithFiniteRowsAndStrips) {
  const testing::CliRun r =
      run("fidelity --size 48x32 --scenes spheres --techniques wedge-3pass,coverage "
          "--oracle-rays 16 --max-search-rays 8 --runs 1 --quiet --out raw --doc page/fidelity.md");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = testing::slurp(path("page/fidelity.md"));
  EXPECT_NE(page.find("penumbra fidelity --size 48x32 --scenes spheres"), std::string::npos);
  for (const std::string technique : {"wedge-3pass", "coverage"}) {
    // "| name | MAE | RMSE | p99 | penumbra MAE | RMSE | p99 | signed | off % | ms | rays |...":
    // nine numbers, none nan or inf.
    const std::regex row("\\| " + technique +
                         " \\| ([0-9.]+) \\| ([0-9.]+) \\| ([0-9.]+) \\| ([0-9.]+) \\| ([0-9.]+) "
                         "\\| ([0-9.]+) \\| ([-+][0-9.]+) \\| ([0-9.]+)% \\| ([0-9.]+) \\| "
                         "(> 8|[0-9]+) \\|");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(page, m, row)) << technique << "\n" << page;
    for (int i = 1; i <= 9; ++i) EXPECT_TRUE(std::isfinite(std::stod(m[i].str()))) << m[i];
    EXPECT_TRUE(std::filesystem::exists(path("page/images/fidelity/spheres-" + technique + ".png")));
  }
  const std::string csv = testing::slurp(path("raw/fidelity.csv"));
  EXPECT_NE(csv.find("spheres,coverage,"), std::string::npos) << csv;
  // No number anywhere printed as nan or inf (words such as "Fernando" contain "nan").
  EXPECT_FALSE(std::regex_search(page, std::regex("[^a-zA-Z](nan|inf)[^a-zA-Z]"))) << page;
}

TEST_F(FidelityCli, RejectsRayTracedTechniqueAndBadSize) {
  testing::CliRun r = run("fidelity --scenes spheres --techniques reference --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not a soft technique"), std::string::npos) << r.err;
  r = run("fidelity --scenes spheres --size 48by32 --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("WIDTHxHEIGHT"), std::string::npos) << r.err;
  r = run("fidelity --scenes spheres --oracle-rays 16 --max-search-rays 16 --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("below"), std::string::npos) << r.err;
}

}  // namespace test_fidelity
}  // namespace penumbra
