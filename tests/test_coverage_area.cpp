// Per-edge coverage of the `coverage` technique against dense sampling of the light: the exact
// area (shape_coverage.h), the float kernel and its SIMD twin (disk_coverage_kernel.h), the
// per-point frame that projects 3D edges onto each light shape (coverage_basis.h), and the
// 2003 paper's coverage table (coverage_table.h). Release run time about 0.6 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "scene/light.h"
#include "shadows/coverage/coverage_basis.h"
#include "shadows/coverage/coverage_table.h"
#include "shadows/coverage/disk_coverage_kernel.h"
#include "shadows/coverage/shape_coverage.h"
#include "shadows/coverage/square_coverage_kernel.h"

namespace penumbra {
namespace test_coverage_area {

constexpr double kPi = 3.14159265358979323846;

double cross2(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

// The definition, counted: the fraction of a grid x grid raster of cell centres over
// [-1, 1]^2 inside the light whose segment from the centre crosses a-b (inside the cone over
// a-b, beyond its line), signed by the turn a -> b. Independent of the formulas under test.
double sampledFraction(LightOutline outline, dvec2 a, dvec2 b, int grid) {
  const double turn = cross2(a, b);
  if (turn == 0.0) return 0.0;
  if (turn < 0.0) std::swap(a, b);
  const double cell = 2.0 / grid;
  long count = 0;
  for (int j = 0; j < grid; ++j) {
    const double y = -1.0 + (j + 0.5) * cell;
    for (int i = 0; i < grid; ++i) {
      const dvec2 x(-1.0 + (i + 0.5) * cell, y);
      if (outline == LightOutline::Disk && glm::dot(x, x) > 1.0) continue;
      if (cross2(a, x) < 0.0 || cross2(x, b) < 0.0) continue;
      if (cross2(b - a, x - a) >= 0.0) continue;  // the centre's side of the edge
      ++count;
    }
  }
  const double area = outline == LightOutline::Disk ? kPi : 4.0;
  const double fraction = double(count) * cell * cell / area;
  return turn > 0.0 ? fraction : -fraction;
}

// Random segments that mostly cross the light: end points in [-1.6, 1.6]^2.
std::vector<std::pair<dvec2, dvec2>> randomSegments(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  std::vector<std::pair<dvec2, dvec2>> out;
  for (int k = 0; k < n; ++k) out.push_back({dvec2(u(rng), u(rng)), dvec2(u(rng), u(rng))});
  return out;
}

// Exact area vs dense sampling, within 1e-4 of the light's area (the bound), for the
// disk (sphere and disk lights) and the square (rectangle lights). A wrong sector or clip
// formula misses by far more.
TEST(CoverageArea, ExactAreaMatchesDenseSamplingOfTheLight) {
  int nonzero = 0;
  for (const LightOutline outline : {LightOutline::Disk, LightOutline::Square}) {
    for (const auto& [a, b] : randomSegments(8, outline == LightOutline::Disk ? 1u : 2u)) {
      const double exact = beyondFraction(outline, a, b);
      const double sampled = sampledFraction(outline, a, b, 2400);
      EXPECT_NEAR(exact, sampled, 1e-4) << "a " << a.x << "," << a.y << " b " << b.x << "," << b.y;
      nonzero += std::fabs(sampled) > 0.01;
    }
  }
  EXPECT_GE(nonzero, 6) << "too few segments crossed the light to test anything";
}

// The edge term restricted to a half-plane (the visible surface's own plane cutting the light:
// insideFractionInHalfPlane) against dense sampling of the light inside that half-plane, and,
// with a half-plane holding the whole light, against the unrestricted term. A clip or sector on
// the wrong side misses by far more than 1e-4 of the light.
TEST(CoverageArea, HalfPlaneTermMatchesDenseSampling) {
  std::mt19937 rng(5u);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi), offset(-0.9, 0.9);
  int nonzero = 0;
  for (const LightOutline outline : {LightOutline::Disk, LightOutline::Square}) {
    for (const auto& [a3, b3] : randomSegments(10, outline == LightOutline::Disk ? 3u : 4u)) {
      dvec2 lo, hi;
      if (!clipToOutline(outline, dvec3(a3, 1.0), dvec3(b3, 1.0), lo, hi)) continue;
      const double phi = angle(rng);
      const dvec2 n(std::cos(phi), std::sin(phi));
      const double h = offset(rng);
      const double exact = insideFractionInHalfPlane(outline, lo, hi, n, h);
      // Sampled: the definition of sampledFraction, restricted to n . x + h > 0.
      const double turn = cross2(lo, hi);
      const dvec2 a = turn > 0.0 ? lo : hi, b = turn > 0.0 ? hi : lo;
      const int grid = 2400;
      const double cell = 2.0 / grid;
      long count = 0;
      for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
          const dvec2 x(-1.0 + (i + 0.5) * cell, -1.0 + (j + 0.5) * cell);
          if (outline == LightOutline::Disk && glm::dot(x, x) > 1.0) continue;
          if (glm::dot(n, x) + h <= 0.0) continue;
          if (cross2(a, x) < 0.0 || cross2(x, b) < 0.0) continue;
          if (cross2(b - a, x - a) >= 0.0) continue;
          ++count;
        }
      const double sampled = (turn > 0.0 ? 1.0 : -1.0) * double(count) * cell * cell /
                             (outline == LightOutline::Disk ? kPi : 4.0);
      EXPECT_NEAR(exact, sampled, 1e-4) << "outline " << int(outline);
      EXPECT_NEAR(insideFractionInHalfPlane(outline, lo, hi, n, 10.0),
                  insideFraction(outline, lo, hi), 1e-12);
      nonzero += std::fabs(sampled) > 0.01;
    }
  }
  std::printf("[ coverage ] half-plane terms tested: %d non-zero\n", nonzero);
  EXPECT_GE(nonzero, 6) << "too few segments crossed the light to test anything";
}

// The float kernels (what `coverage` runs: the disk's for sphere and disk lights, the
// square's for rectangles) against the exact area in double, end points given in homogeneous
// form with random depths W, some behind the point (W < 0): within 1e-5 of the light. And each
// SIMD kernel gives its scalar twin's bits.
class FloatKernels : public ::testing::TestWithParam<LightOutline> {};

TEST_P(FloatKernels, MatchTheExactAreaAndTheirSimdTwins) {
  const LightOutline outline = GetParam();
  const auto one = outline == LightOutline::Disk ? diskCoverageOne : squareCoverageOne;
  const auto scalar_kernel = outline == LightOutline::Disk ? diskCoverageScalar : squareCoverageScalar;
  const auto kernel = outline == LightOutline::Disk ? diskCoverage : squareCoverage;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.6, 1.6), w(-0.5, 3.0);
  const int n = 4099;  // not a multiple of any vector width
  std::vector<float> x0(n), y0(n), w0(n), x1(n), y1(n), w1(n), simd(n), scalar(n);
  double worst = 0.0;
  int crossing = 0;
  for (int k = 0; k < n; ++k) {
    const double wa = w(rng), wb = w(rng);
    const dvec3 a(u(rng) * wa, u(rng) * wa, wa), b(u(rng) * wb, u(rng) * wb, wb);
    x0[k] = float(a.x), y0[k] = float(a.y), w0[k] = float(a.z);
    x1[k] = float(b.x), y1[k] = float(b.y), w1[k] = float(b.z);
    // The reference from the float-rounded inputs, so only the kernel's arithmetic is judged.
    const double exact = beyondFractionHomogeneous(
        outline, dvec3(x0[k], y0[k], w0[k]), dvec3(x1[k], y1[k], w1[k]));
    const float got = one(x0[k], y0[k], w0[k], x1[k], y1[k], w1[k]);
    worst = std::max(worst, std::fabs(double(got) - exact));
    crossing += std::fabs(exact) > 1e-3;
  }
  EXPECT_LE(worst, 1e-5);
  EXPECT_GT(crossing, n / 10);
  const DiskCoverageBatch bs{x0.data(), y0.data(), w0.data(), x1.data(), y1.data(), w1.data(),
                             simd.data()};
  const DiskCoverageBatch bc{x0.data(), y0.data(), w0.data(), x1.data(), y1.data(), w1.data(),
                             scalar.data()};
  kernel(bs, size_t(n), true);
  scalar_kernel(bc, size_t(n));
  for (int k = 0; k < n; ++k) ASSERT_EQ(simd[k], scalar[k]) << "pair " << k;
}

INSTANTIATE_TEST_SUITE_P(CoverageArea, FloatKernels,
                         ::testing::Values(LightOutline::Disk, LightOutline::Square),
                         [](const auto& param_info) {
                           return param_info.param == LightOutline::Disk ? "Disk" : "Square";
                         });

// The frame projects a 3D edge from a point onto each light shape. Against the definition in
// 3D: sample the light (a grid over the disk or rectangle itself, or the sphere's tangent disk)
// and count the light points y whose segment from p passes through the hard quad (the edge
// extruded away from the centre, {c + s (x - c): x on the edge, s >= 1}). The analytic value's
// magnitude must match, and its sign must say the side of the quad's plane p is on, the same
// way for every shape.
TEST(CoverageArea, FrameProjectsEdgesOntoEveryLightShape) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const vec3 c(0.3f, 6.0f, -0.2f);
  const Light lights[] = {
      Light{c, 0.8f, vec3(1), 1.0f},
      diskLight(c, glm::normalize(vec3(0.2f, -1.0f, 0.1f)), 0.8f),
      rectangleLight(c, vec3(1.4f, 0.0f, 0.2f), vec3(-0.1f, 0.0f, 0.7f)),
  };
  int tested = 0, sign_agree = 0, sign_disagree = 0;
  for (const Light& light : lights) {
    for (int k = 0; k < 12; ++k) {
      const dvec3 p(u(rng) * 1.5, 0.0, u(rng) * 1.5);
      // An edge between the point and the light, near the line from p to the centre.
      const dvec3 mid = p + (dvec3(c) - p) * (0.4 + 0.2 * u(rng)) + dvec3(u(rng), 0, u(rng)) * 0.3;
      const dvec3 dir = glm::normalize(dvec3(u(rng), 0.2 * u(rng), u(rng)));
      const dvec3 a = mid - dir * 0.6, b = mid + dir * 0.5;
      CoverageBasis f;
      ASSERT_TRUE(coverageBasis(light, p, f));
      const double analytic = beyondFractionHomogeneous(f.outline, f.homogeneous(a), f.homogeneous(b));
      // Sample points of the light's outline in the frame's own plane (the sphere's tangent
      // disk), mapped back to world.
      const double rt = 1.0 / f.scale_t, rb = 1.0 / f.scale_b;
      const dvec3 plane_c = p + f.n / f.inv_depth + f.t * (-f.offset_t) + f.b * (-f.offset_b);
      const dvec3 qn = glm::cross(a - dvec3(c), b - dvec3(c));
      const int grid = 500;
      long inside = 0, total = 0;
      for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
          const dvec2 s(-1.0 + (i + 0.5) * 2.0 / grid, -1.0 + (j + 0.5) * 2.0 / grid);
          if (f.outline == LightOutline::Disk && glm::dot(s, s) > 1.0) continue;
          ++total;
          const dvec3 y = plane_c + f.t * (s.x * rt) + f.b * (s.y * rb);
          // Segment p -> y against the quad's plane (through c), then inside the quad.
          const double dp = glm::dot(qn, p - dvec3(c)), dy = glm::dot(qn, y - dvec3(c));
          if ((dp > 0) == (dy > 0)) continue;
          const dvec3 z = p + (y - p) * (dp / (dp - dy));
          // z = c + s (x - c) with x on a-b and s >= 1: solve in the plane's 2D basis.
          const dvec3 ea = a - dvec3(c), eb = b - dvec3(c), zc = z - dvec3(c);
          const double det = glm::dot(glm::cross(ea, eb), qn);
          const double alpha = glm::dot(glm::cross(zc, eb), qn) / det;  // z = alpha ea + beta eb
          const double beta = glm::dot(glm::cross(ea, zc), qn) / det;
          if (alpha >= 0 && beta >= 0 && alpha + beta >= 1.0) ++inside;
        }
      }
      const double sampled = double(inside) / double(total);
      EXPECT_NEAR(std::fabs(analytic), sampled, 2e-3) << lightShapeName(light.shape) << " " << k;
      if (sampled > 0.02) {
        ++tested;
        const double side = glm::dot(qn, p - dvec3(c));
        ((side > 0) == (analytic > 0) ? sign_agree : sign_disagree)++;
      }
    }
  }
  EXPECT_GE(tested, 12);
  EXPECT_TRUE(sign_agree == 0 || sign_disagree == 0)
      << "the sign is not the side of the quad's plane: " << sign_agree << " vs " << sign_disagree;
}

// The coverage table (the 2003 paper's texture) against the exact area for segments inside
// the light: mean and max absolute error per table size, for nearest and quadlinear lookup.
// Quadlinear must beat nearest at every size, and the error must fall with the size.
TEST(CoverageArea, QuadlinearTableBeatsNearest) {
  for (const LightOutline outline : {LightOutline::Disk, LightOutline::Square}) {
    double previous_quad = 1e9;
    for (const int n : {8, 16, 32}) {
      if (outline == LightOutline::Square && n == 32) continue;  // slow to build; same trend
      const CoverageTableData table(outline, n);
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> u(-1.6, 1.6);
      double sum_near = 0, sum_quad = 0, max_near = 0, max_quad = 0;
      int count = 0;
      while (count < 4000) {
        const dvec3 a(u(rng), u(rng), 1.0), b(u(rng), u(rng), 1.0);
        dvec2 lo, hi;
        if (!clipToOutline(outline, a, b, lo, hi)) continue;
        const double exact = insideFraction(outline, lo, hi);
        const double e_near = std::fabs(table.lookupInside(lo, hi, CoverageTable::Nearest) - exact);
        const double e_quad =
            std::fabs(table.lookupInside(lo, hi, CoverageTable::Quadlinear) - exact);
        sum_near += e_near, sum_quad += e_quad;
        max_near = std::max(max_near, e_near), max_quad = std::max(max_quad, e_quad);
        ++count;
      }
      std::printf("[ table    ] %-6s n=%2d  nearest mean %.5f max %.4f   quadlinear mean %.5f "
                  "max %.4f\n",
                  outline == LightOutline::Disk ? "disk" : "square", n, sum_near / count,
                  max_near, sum_quad / count, max_quad);
      EXPECT_LT(sum_quad, sum_near) << "n " << n;
      EXPECT_LT(sum_quad / count, previous_quad) << "n " << n;
      previous_quad = sum_quad / count;
    }
  }
}

// The symmetries Funk's report names, which a table could use to shrink: swapping the end
// points negates the fraction, rotating both about the centre keeps it (any angle for a disk,
// quarter turns for a square).
TEST(CoverageArea, SymmetriesOfTheCoverage) {
  for (const auto& [a, b] : randomSegments(50, 3u)) {
    for (const LightOutline outline : {LightOutline::Disk, LightOutline::Square}) {
      const double f = beyondFraction(outline, a, b);
      EXPECT_NEAR(beyondFraction(outline, b, a), -f, 1e-12);
      const dvec2 ra(-a.y, a.x), rb(-b.y, b.x);
      EXPECT_NEAR(beyondFraction(outline, ra, rb), f, 1e-12);
    }
    const double angle = 0.7;
    const auto rot = [&](const dvec2& v) {
      return dvec2(std::cos(angle) * v.x - std::sin(angle) * v.y,
                   std::sin(angle) * v.x + std::cos(angle) * v.y);
    };
    EXPECT_NEAR(beyondFraction(LightOutline::Disk, rot(a), rot(b)),
                beyondFraction(LightOutline::Disk, a, b), 1e-12);
  }
}

}  // namespace test_coverage_area
}  // namespace penumbra
