// Watertightness and fill-rule tests: shadow-volume counting depends on every pixel centre being
// covered by exactly one of the triangles sharing an edge (README, Conventions).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "raster/rasterizer.h"
#include "raster_test_util.h"

namespace penumbra {
namespace test_raster_coverage {

using testing::screenToClip;
using testing::TestRandom;

// Counts per pixel how many triangles cover it: the stencil pass with every pixel holding a
// surface far behind the triangles, z-pass, weight +1 for front faces (facing * payload).
Image<int32_t> coverageCount(const ClipTriangles& tris, int width, int height, bool simd = true) {
  DepthBuffer depth;
  depth.depth.resize(width, height, 1e-6f);
  depth.buildTileRanges();
  Image<int32_t> stencil(width, height, 0);
  Stats stats;
  StencilOptions options;
  options.simd = simd;
  rasterizeStencil(tris, depth, stencil, stats, options);
  return stencil;
}

// A convex polygon fanned around an interior point, at awkward sub-pixel positions: every pixel
// whose centre is strictly inside must be covered once, every pixel outside never.
TEST(RasterCoverage, FanAroundInteriorPointCoversEachInteriorPixelExactlyOnce) {
  const int width = 97, height = 83;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    TestRandom rng(seed);
    const double cx = rng.uniform(30, 60), cy = rng.uniform(30, 50);
    const int sides = 3 + int(rng.uniform(0, 40));
    const double radius = rng.uniform(5, 45), phase = rng.uniform(0, 6.3);
    ClipTriangles tris;
    tris.clip.push_back(screenToClip(cx, cy, 0.5, width, height));
    std::vector<dvec2> ring;
    for (int i = 0; i < sides; ++i) {
      // Decreasing angle with y down runs counter-clockwise as seen on screen: front-facing.
      const double angle = phase - 2.0 * std::numbers::pi * i / sides;
      ring.emplace_back(cx + radius * std::cos(angle), cy + radius * std::sin(angle));
      tris.clip.push_back(screenToClip(ring.back().x, ring.back().y, 0.5, width, height));
    }
    for (int i = 0; i < sides; ++i)
      tris.add(0, uint32_t(1 + i), uint32_t(1 + (i + 1) % sides), 1);
    const Image<int32_t> count = coverageCount(tris, width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const int c = count.at(x, y);
        ASSERT_TRUE(c == 0 || c == 1) << "pixel " << x << "," << y << " covered " << c
                                      << " times (seed " << seed << ")";
        // Distance of the pixel centre inside the polygon (negative outside).
        double inside = 1e9;
        for (int i = 0; i < sides; ++i) {
          const dvec2 a = ring[i], b = ring[(i + 1) % sides];
          const dvec2 edge = b - a, p = dvec2(x + 0.5, y + 0.5) - a, c0 = dvec2(cx, cy) - a;
          const double side = (c0.x * edge.y - c0.y * edge.x) > 0 ? 1.0 : -1.0;
          inside = std::min(inside, side * (p.x * edge.y - p.y * edge.x) / glm::length(edge));
        }
        // Snapping moves vertices by up to 1/32 pixel: only judge pixels clear of the edges.
        if (inside > 0.1) {
          ASSERT_EQ(c, 1) << "hole at " << x << "," << y << " seed " << seed;
        }
        if (inside < -0.1) {
          ASSERT_EQ(c, 0) << "spill at " << x << "," << y << " seed " << seed;
        }
      }
  }
}

// A jittered grid mesh reaching past the image borders and through the near plane: the whole
// screen must be covered exactly once, including across edges produced by clipping.
TEST(RasterCoverage, JitteredGridClippedByNearPlaneAndGuardBandIsWatertight) {
  const int width = 120, height = 90, n = 24;
  TestRandom rng(7);
  ClipTriangles tris;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      // Homogeneous points: the grid spans far beyond the screen, some vertices lie behind the
      // eye (w < 0 after the perspective divide flips them) so near clipping must cut them.
      const double u = double(i) / n * 2 - 1, v = double(j) / n * 2 - 1;
      const double jx = border ? 0 : rng.uniform(-0.03, 0.03), jy = border ? 0 : rng.uniform(-0.03, 0.03);
      const double w = 0.15 + 1.0 * (u + 1) * 0.5 + rng.uniform(0, 0.2);
      const double x = (u * 3000.0 / width + jx) * w, y = (v * 3000.0 / height + jy) * w;
      const double depth_z = 0.3 * w;  // z/w = 0.3: in front of the stored surface
      tris.clip.push_back(vec4(float(x), float(y), float(depth_z), float(w - 0.4)));
    }
  auto idx = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.add(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), 1);
      tris.add(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1), 1);
    }
  const Image<int32_t> count = coverageCount(tris, width, height);
  int covered = 0;
  for (size_t p = 0; p < count.size(); ++p) {
    ASSERT_LE(std::abs(count[p]), 1) << "pixel " << p % width << "," << p / width;
    covered += count[p] != 0;
  }
  // Part of the grid is clipped away by the near plane; the rest must cover without holes:
  // every covered row is one contiguous run.
  EXPECT_GT(covered, 0);
  for (int y = 0; y < height; ++y) {
    int runs = 0;
    for (int x = 0; x < width; ++x)
      runs += count.at(x, y) != 0 && (x == 0 || count.at(x - 1, y) == 0);
    EXPECT_LE(runs, 1) << "row " << y << " has a hole";
  }
}

// Two triangles sharing a diagonal, a vertical and a horizontal edge exactly through pixel
// centres: the top-left rule gives every centre on the shared edge to exactly one triangle.
TEST(RasterCoverage, TopLeftRuleOnEdgesThroughPixelCentres) {
  const int width = 16, height = 16;
  ClipTriangles tris;
  // A square from (2.5, 2.5) to (12.5, 12.5): its edges pass through pixel centres.
  const double lo = 2.5, hi = 12.5, mid = 7.5;
  auto v = [&](double x, double y) {
    tris.clip.push_back(screenToClip(x, y, 0.5, width, height));
    return uint32_t(tris.clip.size() - 1);
  };
  const uint32_t a = v(lo, lo), b = v(hi, lo), c = v(hi, hi), d = v(lo, hi), m = v(mid, mid);
  // Four triangles around the centre, counter-clockwise as seen on screen = front-facing.
  tris.add(b, a, m, 1);
  tris.add(c, b, m, 1);
  tris.add(d, c, m, 1);
  tris.add(a, d, m, 1);
  const Image<int32_t> count = coverageCount(tris, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool inside_closed = x >= 2 && x <= 12 && y >= 2 && y <= 12;
      ASSERT_LE(count.at(x, y), 1) << x << "," << y;
      if (!inside_closed) {
        ASSERT_EQ(count.at(x, y), 0) << x << "," << y;
      }
      // Strict interior and the shared diagonals: exactly once.
      if (x > 2 && x < 12 && y > 2 && y < 12) {
        ASSERT_EQ(count.at(x, y), 1) << x << "," << y;
      }
    }
  // The outer square's own edges: top and left edges are in, bottom and right are out.
  EXPECT_EQ(count.at(5, 2), 1);   // top edge
  EXPECT_EQ(count.at(2, 5), 1);   // left edge
  EXPECT_EQ(count.at(5, 12), 0);  // bottom edge
  EXPECT_EQ(count.at(12, 5), 0);  // right edge
}

// Reversing a triangle's winding must not move its pixels: shadow-volume light caps are the
// scene's own triangles, sometimes counted with the opposite orientation.
TEST(RasterCoverage, WindingDoesNotChangeCoverageOrDepth) {
  const int width = 64, height = 64;
  TestRandom rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    ClipTriangles fwd, rev;
    for (int k = 0; k < 3; ++k) {
      const vec4 p = screenToClip(rng.uniform(-5, 70), rng.uniform(-5, 70), rng.uniform(0.1, 0.9),
                                  width, height);
      fwd.clip.push_back(p);
      rev.clip.push_back(p);
    }
    fwd.add(0, 1, 2, 1);
    rev.add(0, 2, 1, 1);
    const Image<int32_t> a = coverageCount(fwd, width, height);
    const Image<int32_t> b = coverageCount(rev, width, height);
    for (size_t p = 0; p < a.size(); ++p) ASSERT_EQ(a[p], -b[p]) << "trial " << trial;
  }
}

}  // namespace test_raster_coverage
}  // namespace penumbra
