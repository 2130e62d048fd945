#include <gtest/gtest.h>

#include <cmath>

#include "core/parallel.h"
#include "core/view.h"
#include "raster/rasterizer.h"
#include "raster/tile_kernels.h"
#include "raster_test_util.h"

namespace penumbra {
namespace test_raster_depth {

using testing::screenToClip;
using testing::TestRandom;

struct DepthResult {
  Image<float> depth;
  Image<uint32_t> primitive;
  Stats stats;
};

DepthResult drawSoup(const ClipTriangles& tris, int width, int height, bool simd) {
  DepthResult r;
  r.depth.resize(width, height, 0.0f);
  r.primitive.resize(width, height, 0xffffffffu);
  rasterizeDepth(tris, r.depth, r.primitive, r.stats, simd);
  return r;
}

ClipTriangles randomSoup(int count, int width, int height, uint64_t seed) {
  TestRandom rng(seed);
  ClipTriangles tris;
  for (int t = 0; t < count; ++t) {
    const double cx = rng.uniform(-20, width + 20), cy = rng.uniform(-20, height + 20);
    const double size = rng.uniform(1, 60);
    for (int k = 0; k < 3; ++k) {
      tris.clip.push_back(screenToClip(cx + rng.uniform(-size, size), cy + rng.uniform(-size, size),
                                       rng.uniform(0.01, 1.0), width, height));
    }
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  return tris;
}

// The SIMD kernels and their scalar twins must agree bit for bit, or "scalar build passes"
// would say nothing about the shipped SIMD path.
TEST(RasterDepth, SimdAndScalarTwinsAreIdentical) {
  if (!simdKernelsAvailable()) GTEST_SKIP() << "scalar-only build: no SIMD kernels to compare";
  const int width = 203, height = 117;  // not multiples of the tile or lane count
  const ClipTriangles tris = randomSoup(3000, width, height, 11);
  const DepthResult simd = drawSoup(tris, width, height, true);
  const DepthResult scalar = drawSoup(tris, width, height, false);
  EXPECT_TRUE(simd.depth == scalar.depth);
  EXPECT_TRUE(simd.primitive == scalar.primitive);
  EXPECT_TRUE(simd.stats.sameCounters(scalar.stats));
  EXPECT_GT(simd.stats.pixels_rasterized, 0u);
}

// Tiles are owned by one worker at a time: the thread count must not change a single bit.
TEST(RasterDepth, OneAndManyThreadsAreIdentical) {
  const int width = 320, height = 200;
  const ClipTriangles tris = randomSoup(4000, width, height, 5);
  DepthResult one, many;
  {
    ThreadLimit limit(1);
    one = drawSoup(tris, width, height, true);
  }
  {
    ThreadLimit limit(4);
    many = drawSoup(tris, width, height, true);
  }
  EXPECT_TRUE(one.depth == many.depth);
  EXPECT_TRUE(one.primitive == many.primitive);
  EXPECT_TRUE(one.stats.sameCounters(many.stats));
}

// Depth is near / distance: a plane facing the camera at distance 4 must read 0.1 / 4 on every
// pixel (the oracle reconstructs shaded points from these values).
TEST(RasterDepth, PlaneDepthMatchesProjection) {
  const int width = 80, height = 60;
  const View view = View::lookAt(width, height, vec3(0, 0, 0), vec3(0, 0, -1), vec3(0, 1, 0), 60, 0.1f);
  ClipTriangles tris;
  for (vec3 p : {vec3(-50, -50, -4), vec3(50, -50, -4), vec3(50, 50, -4), vec3(-50, 50, -4)})
    tris.clip.push_back(view.toClip(vec4(p, 1)));
  tris.add(0, 1, 2, 0);
  tris.add(0, 2, 3, 1);
  const DepthResult r = drawSoup(tris, width, height, true);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      ASSERT_NEAR(r.depth.at(x, y), 0.1f / 4.0f, 1e-7f) << x << "," << y;
      const dvec3 p = view.unproject(x, y, r.depth.at(x, y));
      ASSERT_NEAR(p.z, -4.0, 1e-4);
    }
}

// The closer of two overlapping triangles wins regardless of drawing order.
TEST(RasterDepth, CloserTriangleWins) {
  const int width = 40, height = 40;
  ClipTriangles tris;
  for (double d : {0.2, 0.6, 0.4}) {
    const uint32_t base = uint32_t(tris.clip.size());
    tris.clip.push_back(screenToClip(-10, -10, d, width, height));
    tris.clip.push_back(screenToClip(100, -10, d, width, height));
    tris.clip.push_back(screenToClip(-10, 100, d, width, height));
    tris.add(base, base + 1, base + 2, int32_t(base / 3));
  }
  const DepthResult r = drawSoup(tris, width, height, true);
  for (size_t p = 0; p < r.depth.size(); ++p) {
    ASSERT_EQ(r.primitive[p], 1u);
    ASSERT_FLOAT_EQ(r.depth[p], 0.6f);
  }
}

// NaN, infinite and eye-plane vertices are dropped without a crash (bad input must never
// take the renderer down), and do not disturb the valid triangles around them.
TEST(RasterDepth, NonFiniteAndDegenerateTrianglesAreDropped) {
  const int width = 32, height = 32;
  ClipTriangles tris;
  const float nan = std::nanf(""), inf = INFINITY;
  tris.clip = {vec4(nan, 0, 0.5f, 1), vec4(1, 0, 0.5f, 1), vec4(0, 1, 0.5f, 1),
               vec4(inf, 0, 0.5f, 1), vec4(0, 0, 0, 0),    vec4(0, 0, 0, 0),
               vec4(-1, -1, 0.5f, 1), vec4(3, -1, 0.5f, 1), vec4(-1, 3, 0.5f, 1)};
  tris.add(0, 1, 2, 0);
  tris.add(3, 1, 2, 1);
  tris.add(4, 5, 1, 2);
  tris.add(1, 1, 2, 3);  // zero area
  tris.add(6, 7, 8, 4);  // covers the whole screen
  const DepthResult r = drawSoup(tris, width, height, true);
  for (size_t p = 0; p < r.depth.size(); ++p) ASSERT_EQ(r.primitive[p], 4u);
}

// Tile z-min/z-max bound every pixel of their tile at every level (the culling relies on it).
TEST(RasterDepth, TileRangesBoundTheirPixels) {
  const int width = 203, height = 117;
  const ClipTriangles tris = randomSoup(500, width, height, 9);
  DepthBuffer buffer;
  Image<uint32_t> ids(width, height, 0);
  buffer.depth.resize(width, height, 0.0f);
  Stats stats;
  rasterizeDepth(tris, buffer.depth, ids, stats, true);
  buffer.buildTileRanges();
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    const TileDepthRange& r = buffer.tileRange(level);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float d = buffer.depth.at(x, y);
        ASSERT_LE(r.zmin.at(x >> level, y >> level), d);
        ASSERT_GE(r.zmax.at(x >> level, y >> level), d);
      }
  }
  EXPECT_THROW(buffer.tileRange(9), Error);
}

// The eye pass takes its tile ranges from each bin tile as it draws it: they must be exactly
// the ranges built from the finished buffer, or culling decisions (and counters) would change
// with the pass that built them. Sizes cut tiles at the image's edge at every level (odd, one
// pixel wide, one tile and a bit), and a soup that leaves background tiles.
TEST(RasterDepth, TileRangesTakenWhileDrawingEqualThoseBuiltAfter) {
  const int sizes[][2] = {{203, 117}, {1, 45}, {33, 1}, {64, 64}, {257, 300}};
  for (const auto& size : sizes) {
    const int width = size[0], height = size[1];
    const ClipTriangles tris = randomSoup(300, width, height, 17);
    DepthBuffer drawn, after;
    Image<uint32_t> drawn_ids(width, height, 0), after_ids(width, height, 0);
    drawn.depth.resize(width, height, 0.0f);
    after.depth.resize(width, height, 0.0f);
    Stats stats;
    rasterizeDepth(tris, drawn, drawn_ids, stats, true);
    rasterizeDepth(tris, after.depth, after_ids, stats, true);
    after.buildTileRanges();
    ASSERT_TRUE(drawn.depth == after.depth);
    for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
      EXPECT_TRUE(drawn.tileRange(level).zmin == after.tileRange(level).zmin)
          << width << "x" << height << " level " << level;
      EXPECT_TRUE(drawn.tileRange(level).zmax == after.tileRange(level).zmax)
          << width << "x" << height << " level " << level;
    }
  }
}

}  // namespace test_raster_depth
}  // namespace penumbra
