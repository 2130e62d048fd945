// The oracle's light sampling: strata, the square-to-disk map and the cone toward a sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "shadows/stages/light_sampling/light_sampling.h"

namespace penumbra {
namespace test_reference_sampling {

// The grid must multiply to n and be as square as n allows; otherwise samples would be lost
// or strata needlessly elongated.
TEST(ReferenceSampling, StrataGrid) {
  const int cases[][3] = {{1, 1, 1}, {256, 16, 16}, {1024, 32, 32}, {12, 4, 3}, {7, 7, 1},
                          {4096, 64, 64}, {18, 6, 3}};
  for (const auto& c : cases) {
    const StrataGrid g = strataGrid(c[0]);
    EXPECT_EQ(g.columns, c[1]) << c[0];
    EXPECT_EQ(g.rows, c[2]) << c[0];
  }
  EXPECT_THROW(strataGrid(0), Error);
}

// One sample per stratum, reproducible per pixel and seed, different between pixels. If this
// failed, the estimate would not be stratified or would depend on something besides the pixel.
TEST(ReferenceSampling, StratifiedSamplesOnePerCell) {
  constexpr int kN = 12;  // 4 x 3
  std::vector<vec2> a(kN), b(kN), c(kN);
  stratifiedSamples(kN, 5, 10, 20, a.data());
  stratifiedSamples(kN, 5, 10, 20, b.data());
  stratifiedSamples(kN, 5, 11, 20, c.data());
  for (int i = 0; i < kN; ++i) {
    const int column = i % 4, row = i / 4;
    EXPECT_GE(a[i].x, column / 4.0);
    EXPECT_LT(a[i].x, (column + 1) / 4.0);
    EXPECT_GE(a[i].y, row / 3.0);
    EXPECT_LT(a[i].y, (row + 1) / 3.0);
    EXPECT_EQ(a[i], b[i]);
    EXPECT_NE(a[i], c[i]);
  }
}

// The concentric map keeps areas: a quarter of the square's area lands inside radius 1/2. A
// polar map (radius = u) would put half there, and the light would be sampled non-uniformly.
TEST(ReferenceSampling, ConcentricDiskPreservesArea) {
  constexpr int kGrid = 200;
  int inner = 0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const DiskPoint p = concentricDisk(vec2((i + 0.5f) / kGrid, (j + 0.5f) / kGrid));
      ASSERT_LE(p.radius, 1.0f);
      ASSERT_NEAR(p.cos_phi * p.cos_phi + p.sin_phi * p.sin_phi, 1.0f, 1e-6f);
      inner += p.radius < 0.5f ? 1 : 0;
      // The same point in Cartesian form stays in its quadrant: the map is a bijection that
      // keeps the square's quadrants (a sign error would fold the disk onto half of itself).
      const float px = p.radius * p.cos_phi, py = p.radius * p.sin_phi;
      ASSERT_TRUE((px >= -1e-6f) == (i >= kGrid / 2) || std::abs(px) < 1e-6f) << i << "," << j;
      ASSERT_TRUE((py >= -1e-6f) == (j >= kGrid / 2) || std::abs(py) < 1e-6f) << i << "," << j;
    }
  }
  EXPECT_NEAR(double(inner) / (kGrid * kGrid), 0.25, 0.005);
}

// Directions stay inside the tangent cone, land on the sphere, and are uniform in solid angle:
// the share within angle alpha of the axis is (1 - cos alpha) / (1 - cos theta_max). Sampling
// the papers' facing disk instead would give sin^2 alpha / sin^2 theta_max (0.333 vs 0.268).
TEST(ReferenceSampling, ConeIsUniformInSolidAngleAndHitsTheSphere) {
  const dvec3 from(0.3, -0.2, 0.1);
  const dvec3 center(1.0, 2.0, -1.5);
  const double d = glm::length(center - from);
  const double radius = d * std::sin(glm::radians(60.0));  // theta_max = 60 degrees
  const SphereCone cone = makeSphereCone(from, center, radius);
  EXPECT_NEAR(cone.one_minus_cos_max, 0.5, 1e-7);
  EXPECT_NEAR(glm::dot(cone.tangent, cone.axis), 0.0, 1e-6);
  EXPECT_NEAR(glm::dot(cone.bitangent, cone.axis), 0.0, 1e-6);
  EXPECT_NEAR(glm::dot(cone.tangent, cone.bitangent), 0.0, 1e-6);

  constexpr int kN = 4096;
  std::vector<vec2> u(kN);
  stratifiedSamples(kN, 3, 0, 0, u.data());
  const double cos_alpha = std::cos(glm::radians(30.0));
  int within = 0;
  dvec3 mean(0.0);
  for (const vec2& s : u) {
    const ConeSample sample = sampleSphereCone(cone, concentricDisk(s));
    const dvec3 direction(sample.direction);
    const double cos_theta = glm::dot(direction, dvec3(cone.axis));
    ASSERT_NEAR(glm::length(direction), 1.0, 1e-6);
    ASSERT_GE(cos_theta, 0.5 - 1e-6);
    const dvec3 on_sphere = from + direction * double(sample.distance);
    ASSERT_NEAR(glm::length(on_sphere - center), radius, 1e-5 * d);
    ASSERT_LE(sample.distance, d);  // the near side of the sphere
    within += cos_theta > cos_alpha ? 1 : 0;
    mean += direction;
  }
  EXPECT_NEAR(double(within) / kN, (1.0 - cos_alpha) / 0.5, 0.005);
  EXPECT_NEAR(glm::dot(glm::normalize(mean), dvec3(cone.axis)), 1.0, 1e-6);
}

// A tiny, distant light: the cone must not collapse to its axis by cancellation in
// 1 - sqrt(1 - (r/d)^2), or soft shadows of small lights would turn hard.
TEST(ReferenceSampling, TinyLightKeepsItsCone) {
  const SphereCone cone = makeSphereCone(dvec3(0.0), dvec3(0.0, 0.0, 1000.0), 1e-6);
  EXPECT_NEAR(cone.one_minus_cos_max, 0.5e-18, 1e-24);
  const ConeSample rim = sampleSphereCone(cone, DiskPoint{1.0f, 1.0f, 0.0f});
  // sin of the rim's angle to the axis is r / d = 1e-9
  EXPECT_NEAR(glm::length(glm::cross(dvec3(rim.direction), dvec3(cone.axis))), 1e-9, 1e-12);
}

}  // namespace test_reference_sampling
}  // namespace penumbra
