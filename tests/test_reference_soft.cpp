// The oracle's soft shadows against an analytic penumbra: a disk over a ground plane under a
// spherical light centred above it, integrated here by brute-force quadrature over the light's
// cap (no code shared with the oracle's sampling).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/parallel.h"
#include "shadows/reference/reference_technique.h"
#include "test_reference_fixture.h"

namespace penumbra {
namespace test_reference_soft {

using reference_test::coveredPixels;
using reference_test::groundEyeBuffers;
using reference_test::groundPoint;
using reference_test::horizontalDisk;
using reference_test::horizontalQuad;
using reference_test::makeScene;
using reference_test::referenceConfig;
using reference_test::renderReference;

constexpr double kPi = 3.14159265358979323846;
constexpr float kGroundHalf = 4.0f;
constexpr double kDiskRadius = 1.0;  // R
constexpr double kDiskHeight = 1.0;  // h
constexpr double kLightHeight = 4.0; // H
constexpr double kLightRadius = 1.0; // r

struct DiskScene {
  Light light;
  Scene scene;
  View view;
  EyeBuffers eye;
};

// Looks straight down on the disk's axis; ground triangles are ids 0-1, the disk follows.
DiskScene diskScene(int size) {
  DiskScene d;
  d.light.center = vec3(0.0f, float(kLightHeight), 0.0f);
  d.light.radius = float(kLightRadius);
  d.scene = makeScene({horizontalQuad("ground", 0.0f, -kGroundHalf, -kGroundHalf, kGroundHalf,
                                      kGroundHalf),
                       horizontalDisk(float(kDiskHeight), float(kDiskRadius), 256)},
                      d.light);
  d.view = View::lookAt(size, size, vec3(0.0f, 6.0f, 0.0f), vec3(0.0f), vec3(0, 0, -1), 45.0f,
                        0.1f);
  d.eye = groundEyeBuffers(d.view, kGroundHalf, 0.0);
  return d;
}

TechniqueConfig softOptions(int rays, uint64_t seed = 1) { return referenceConfig(rays, seed); }

// Fraction of the light's cap seen from ground point (rho, 0, 0) that the disk leaves
// unblocked: midpoint rule in (theta, phi) with the solid-angle weight sin(theta).
double analyticVisibility(double rho) {
  const dvec3 g(rho, 0.0, 0.0);
  const dvec3 c(0.0, kLightHeight, 0.0);
  const double d = glm::length(c - g);
  const dvec3 axis = (c - g) / d;
  const dvec3 t = glm::normalize(glm::cross(axis, dvec3(0, 0, 1)));
  const dvec3 b = glm::cross(axis, t);
  const double theta_max = std::asin(kLightRadius / d);
  constexpr int kTheta = 160, kPhi = 320;
  double total = 0.0, blocked = 0.0;
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * theta_max / kTheta;
    const double weight = std::sin(theta);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / kPhi;
      const dvec3 dir = axis * std::cos(theta) +
                        (t * std::cos(phi) + b * std::sin(phi)) * std::sin(theta);
      const dvec3 hit = g + dir * (kDiskHeight / dir.y);
      total += weight;
      if (hit.x * hit.x + hit.z * hit.z <= kDiskRadius * kDiskRadius) blocked += weight;
    }
  }
  return 1.0 - blocked / total;
}

// Checks the penumbra everywhere on the ground against the quadrature (visibility depends only
// on the distance rho from the axis), and its extent against similar triangles: a light of
// radius r at height H and a disk of radius R at height h give an umbra out to
// (R H - r h) / (H - h) and a penumbra out to (R H + r h) / (H - h). If this failed, the oracle
// would sample the light wrongly (not uniform in solid angle, wrong cap, biased strata).
TEST(ReferenceSoft, DiskPenumbraMatchesQuadrature) {
  const DiskScene d = diskScene(64);
  const TechniqueResult result =
      renderReference(softOptions(1024), d.scene, d.light, d.view, d.eye);
  const double pixel = 2.0 * 6.0 * std::tan(kPi / 8.0) / d.view.height;  // ground metres
  const double inner = (kDiskRadius * kLightHeight - kLightRadius * kDiskHeight) /
                       (kLightHeight - kDiskHeight);
  const double outer = (kDiskRadius * kLightHeight + kLightRadius * kDiskHeight) /
                       (kLightHeight - kDiskHeight);

  std::vector<double> table;  // analytic visibility every 0.01 m of rho
  constexpr double kStep = 0.01;
  for (double rho = 0.0; rho < 6.0; rho += kStep) {
    if (rho > outer + 0.2) break;  // fully lit from there on
    table.push_back(analyticVisibility(rho));
  }
  auto expected = [&](double rho) {
    const double f = rho / kStep;
    const size_t i = size_t(f);
    if (i + 1 >= table.size()) return 1.0;
    return table[i] + (table[i + 1] - table[i]) * (f - double(i));
  };

  double signed_sum = 0.0;
  int in_penumbra = 0;
  for (int y = 0; y < d.view.height; ++y) {
    for (int x = 0; x < d.view.width; ++x) {
      dvec3 g;
      ASSERT_TRUE(groundPoint(d.view, x + 0.5, y + 0.5, 0.0, g));
      const double rho = std::hypot(g.x, g.z);
      const double v = result.visibility.at(x, y);
      EXPECT_NEAR(v, expected(rho), 0.03) << "pixel " << x << "," << y << " rho " << rho;
      if (rho < inner - 2.0 * pixel) {
        EXPECT_EQ(v, 0.0) << "umbra pixel " << x << "," << y;
      }
      if (rho > outer + 2.0 * pixel) {
        EXPECT_EQ(v, 1.0) << "lit pixel " << x << "," << y;
      }
      if (v > 0.0 && v < 1.0) {
        ++in_penumbra;
        signed_sum += v - expected(rho);
      }
    }
  }
  EXPECT_GT(in_penumbra, 300);
  // Noise averages out over the penumbra (to about 2e-4 here); a bias does not: moving ray
  // origins off the surface by 1/8 of a pixel footprint already shifts the mean by 0.005.
  EXPECT_NEAR(signed_sum / in_penumbra, 0.0, 0.003) << "over " << in_penumbra << " pixels";
  // Along the row through the axis, outward from it: visibility rises monotonically (up to
  // sampling noise), reaches 0 last and 1 first where similar triangles say, within 2 pixels.
  const int row = d.view.height / 2;
  double previous = 0.0, last_zero = -1.0, first_one = -1.0;
  for (int x = d.view.width / 2; x < d.view.width; ++x) {
    dvec3 g;
    ASSERT_TRUE(groundPoint(d.view, x + 0.5, row + 0.5, 0.0, g));
    const double rho = std::hypot(g.x, g.z);
    const double v = result.visibility.at(x, row);
    EXPECT_GE(v, previous - 0.02) << "not monotone at pixel " << x;
    previous = v;
    if (v == 0.0) last_zero = rho;
    if (v == 1.0 && first_one < 0.0) first_one = rho;
  }
  EXPECT_EQ(result.visibility.at(d.view.width / 2, row), 0.0f);  // umbra at the centre
  EXPECT_EQ(result.visibility.at(0, 0), 1.0f);                     // far away: lit
  EXPECT_NEAR(last_zero, inner, 2.0 * pixel);
  EXPECT_NEAR(first_one, outer, 2.0 * pixel);
  EXPECT_EQ(result.stats.rays, uint64_t(coveredPixels(d.eye)) * 1024u);
}

// The oracle is a pure function of its inputs and seed. If this failed, results would depend
// on thread scheduling (shared random state, racy writes) or ignore the seed.
TEST(ReferenceSoft, DeterministicAcrossRunsThreadsAndPackets) {
  const DiskScene d = diskScene(32);
  const TechniqueConfig options = softOptions(64, 7);
  const TechniqueResult a = renderReference(options, d.scene, d.light, d.view, d.eye);
  const TechniqueResult b = renderReference(options, d.scene, d.light, d.view, d.eye);
  EXPECT_TRUE(a.visibility == b.visibility);

  TechniqueResult one, two;
  {
    ThreadLimit limit(1);
    one = renderReference(options, d.scene, d.light, d.view, d.eye);
  }
  {
    ThreadLimit limit(2);
    two = renderReference(options, d.scene, d.light, d.view, d.eye);
  }
  EXPECT_TRUE(one.visibility == a.visibility);
  EXPECT_TRUE(two.visibility == a.visibility);
  EXPECT_TRUE(one.stats.sameCounters(two.stats));

  RenderContext single;
  single.simd = false;  // rtcOccluded1 instead of 16-ray packets
  const TechniqueResult c = renderReference(options, d.scene, d.light, d.view, d.eye, single);
  EXPECT_TRUE(c.visibility == a.visibility);

  const TechniqueResult other =
      renderReference(softOptions(64, 8), d.scene, d.light, d.view, d.eye);
  EXPECT_FALSE(other.visibility == a.visibility);  // the seed moves the jitter
}

// Points inside the light sphere see all of it and trace no rays. If this failed, points
// inside the light would be shadowed by the geometry around them, or their rays counted.
TEST(ReferenceSoft, PointsInsideTheLightAreLit) {
  DiskScene d = diskScene(32);
  Light inside;
  inside.center = vec3(0.0f, 0.2f, 0.0f);  // under the disk, touching the ground
  inside.radius = 1.0f;
  const TechniqueResult result =
      renderReference(softOptions(16), d.scene, inside, d.view, d.eye);
  int inside_pixels = 0, outside_pixels = 0;
  for (int y = 0; y < d.view.height; ++y) {
    for (int x = 0; x < d.view.width; ++x) {
      dvec3 g;
      ASSERT_TRUE(groundPoint(d.view, x + 0.5, y + 0.5, 0.0, g));
      const double distance = glm::length(g - dvec3(inside.center));
      if (distance < 0.95) {
        EXPECT_EQ(result.visibility.at(x, y), 1.0f) << "pixel " << x << "," << y;
        ++inside_pixels;
      } else if (distance > 1.05) {
        ++outside_pixels;
      }
    }
  }
  EXPECT_GT(inside_pixels, 20);
  EXPECT_LE(result.stats.rays, uint64_t(coveredPixels(d.eye) - inside_pixels) * 16u);
  EXPECT_GE(result.stats.rays, uint64_t(outside_pixels) * 16u);
}

}  // namespace test_reference_soft
}  // namespace penumbra
