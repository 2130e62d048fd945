// forEachCullRect (raster/cull_tiles.h): merged rectangles and the bin-tile pre-test must give
// exactly the per-culling-tile walk of the papers: the same pixels drawn with the same code, and
// the same tested / culled tallies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/parallel.h"
#include "raster/binning.h"
#include "raster/cull_tiles.h"
#include "raster/rasterizer.h"
#include "raster/triangle_setup.h"
#include "raster_test_util.h"

namespace penumbra {
namespace test_raster_cull_tiles {

using testing::TestRandom;

// Pixel state after a walk: 0 not drawn, else the code it was drawn with (drawn twice: -1).
struct Walk {
  std::vector<int> code;
  CullTally tally;
};

// A depth buffer of random surfaces and background holes, so tile ranges vary.
DepthBuffer randomDepth(int width, int height, TestRandom& random) {
  DepthBuffer depth;
  depth.depth.resize(width, height, 0.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool hole = (x / 7 + y / 5) % 9 == 0;
      depth.depth.at(x, y) = hole ? 0.0f : float(0.2 + 0.6 * (x + 2 * y) / (width + 2 * height) +
                                                 0.05 * random.uniform());
    }
  depth.buildTileRanges();
  return depth;
}

TEST(RasterCullTiles, MergedWalkEqualsPerTileWalk) {
  constexpr int kWidth = 200, kHeight = 150;
  TestRandom random(11);
  const DepthBuffer depth = randomDepth(kWidth, kHeight, random);
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    for (int trial = 0; trial < 40; ++trial) {
      // A monotonic decision like the papers' tests (cull_tiles.h): part 1 culled when a
      // plane over the box is negative at its maximum, part 2 when the tile lies behind a depth.
      const double a = random.uniform(-1, 1), b = random.uniform(-1, 1);
      const double c = random.uniform(-150, 150);
      const float z = float(random.uniform(0.1, 0.9));
      auto decide = [&](const TileEdges& r, float zmin, float zmax) {
        const double top = a * (a >= 0 ? r.x1 : r.x0) + b * (b >= 0 ? r.y1 : r.y0) + c;
        int parts = 0;
        if (top >= 0) parts |= 1;
        if (zmax > 0 && !(zmax < z)) parts |= 2;
        (void)zmin;
        return parts;
      };
      // A rect within one bin tile, as the binner hands them out.
      const int bx = int(random.uniform(0, 7)) * kBinTileSize;
      const int by = int(random.uniform(0, 5)) * kBinTileSize;
      TileEdges e{};
      e.tx0 = bx;
      e.ty0 = by;
      e.x0 = std::min(kWidth - 1, bx + int(random.uniform(0, 20)));
      e.y0 = std::min(kHeight - 1, by + int(random.uniform(0, 20)));
      e.x1 = std::min(kWidth - 1, e.x0 + int(random.uniform(0, 32)));
      e.y1 = std::min(kHeight - 1, e.y0 + int(random.uniform(0, 32)));
      e.x1 = std::min(e.x1, bx + kBinTileSize - 1);
      e.y1 = std::min(e.y1, by + kBinTileSize - 1);

      // Edges that hold the whole rect (every edge function 0).
      const SetupTriangle triangle{};

      Walk merged{std::vector<int>(size_t(kWidth) * kHeight, 0), {}};
      TileEdges rect = e;
      forEachCullRect(
          triangle, rect, depth, level, decide,
          [&](const TileEdges& r, int code) {
            for (int y = r.y0; y <= r.y1; ++y)
              for (int x = r.x0; x <= r.x1; ++x) {
                int& p = merged.code[size_t(y) * kWidth + x];
                p = p == 0 ? code : -1;
              }
          },
          merged.tally);

      // The per-tile walk: every culling tile the rect touches, decided on its part of the rect.
      Walk reference{std::vector<int>(size_t(kWidth) * kHeight, 0), {}};
      const TileDepthRange& range = depth.tileRange(level);
      const int size = 1 << level;
      for (int cy = e.y0 >> level; cy <= (e.y1 >> level); ++cy)
        for (int cx = e.x0 >> level; cx <= (e.x1 >> level); ++cx) {
          TileEdges sub = e;
          sub.x0 = std::max(e.x0, cx * size);
          sub.y0 = std::max(e.y0, cy * size);
          sub.x1 = std::min(e.x1, cx * size + size - 1);
          sub.y1 = std::min(e.y1, cy * size + size - 1);
          const int code = decide(sub, range.zmin.at(cx, cy), range.zmax.at(cx, cy));
          ++reference.tally.tested;
          reference.tally.culled += code == 0;
          for (int y = sub.y0; y <= sub.y1 && code != 0; ++y)
            for (int x = sub.x0; x <= sub.x1; ++x) reference.code[size_t(y) * kWidth + x] = code;
        }
      // If it failed: merging drew a pixel twice, with another tile's code or not at all, or
      // the bin-tile pre-test culled a tile the per-tile test keeps (changing the image), or
      // the counters no longer count the papers' per-tile tests.
      ASSERT_EQ(merged.code, reference.code) << "level " << level << " trial " << trial;
      EXPECT_EQ(merged.tally.tested, reference.tally.tested) << "level " << level;
      EXPECT_EQ(merged.tally.culled, reference.tally.culled) << "level " << level;
    }
  }
}

// Long slanted triangles, like shadow-volume quads and wedge faces, at any angle, starting up to
// `reach` pixels off the image and up to `longest` pixels long (clipped to the guard band).
ClipTriangles slantedTriangles(int count, int width, int height, uint64_t seed,
                               double reach = 100, double longest = 900) {
  TestRandom random(seed);
  ClipTriangles tris;
  for (int t = 0; t < count; ++t) {
    const double x = random.uniform(-reach, width + reach);
    const double y = random.uniform(-reach, height + reach);
    const double angle = random.uniform(0, 6.2832), length = random.uniform(5, longest);
    const double width_px = random.uniform(0.3, 40);
    const double dx = std::cos(angle), dy = std::sin(angle);
    tris.clip.push_back(testing::screenToClip(x, y, 0.5, width, height));
    tris.clip.push_back(testing::screenToClip(x + dx * length, y + dy * length, 0.5, width, height));
    tris.clip.push_back(testing::screenToClip(x + dx * length - dy * width_px,
                                              y + dy * length + dx * width_px, 0.5, width, height));
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  return tris;
}

// Every (triangle, bin tile) pair of `setup` in a width x height image: binned exactly when
// setupTileEdges finds the triangle in the tile.
void expectBinnedExactly(const std::vector<SetupTriangle>& setup, int width, int height,
                         double reach) {
  const TileBins bins = binTriangles(setup, width, height);
  size_t pairs = 0;
  for (size_t tile = 0; tile < bins.tileCount(); ++tile) {
    const int tx = int(tile % size_t(bins.tiles_x)), ty = int(tile / size_t(bins.tiles_x));
    const int x0 = tx * kBinTileSize, y0 = ty * kBinTileSize;
    const int x1 = std::min(width, x0 + kBinTileSize) - 1;
    const int y1 = std::min(height, y0 + kBinTileSize) - 1;
    std::vector<bool> binned(setup.size(), false);
    for (uint32_t k = bins.offsets[tile]; k < bins.offsets[tile + 1]; ++k)
      binned[bins.triangles[k]] = true;
    for (size_t i = 0; i < setup.size(); ++i) {
      TileEdges e;
      const bool meets = setupTileEdges(setup[i], x0, y0, x1, y1, e);
      // If it failed: a tile was handed a triangle it does not hold (counted as a culling test
      // that no per-tile walk would make), or was not handed one it holds (lost pixels).
      ASSERT_EQ(binned[i], meets) << "triangle " << i << " tile " << tx << "," << ty
                                  << ", reach " << reach;
      pairs += meets;
    }
  }
  EXPECT_GT(pairs, 2000u) << "reach " << reach;
}

// The binner hands a triangle to exactly the bin tiles where setupTileEdges finds it: the
// passes' tile counters rely on it (forEachCullRect tallies a culled pair without setting up
// its edges), and a missing tile would lose pixels. The second set's triangles run up to 20000
// pixels, across the guard band, as volume quads extruded to infinity do: their edge values are
// far larger than a tile's, and the per-row bounds must still be exact to the tile.
TEST(RasterCullTiles, BinnerHandsOutExactlyTheTilesTheEdgesMeet) {
  constexpr int kWidth = 333, kHeight = 210;
  for (const auto& [reach, longest] : {std::pair{100.0, 900.0}, std::pair{300.0, 20000.0}}) {
    const std::vector<SetupTriangle> setup = setupTriangles(
        slantedTriangles(2000, kWidth, kHeight, 3, reach, longest), kWidth, kHeight);
    expectBinnedExactly(setup, kWidth, kHeight, reach);
  }
}

// Binning counts and fills its lists in runs of triangles at once: each tile's list must still
// hold exactly its triangles in increasing order (the passes resolve depth ties by that order)
// for any thread count. Enough triangles for several runs; the reference walks every
// (triangle, tile) pair in order.
TEST(RasterCullTiles, BinsListEachTilesTrianglesInOrderAcrossRuns) {
  constexpr int kWidth = 333, kHeight = 210;
  const std::vector<SetupTriangle> setup =
      setupTriangles(slantedTriangles(30000, kWidth, kHeight, 5), kWidth, kHeight);
  ASSERT_GT(setup.size(), 3u * 4096u);  // several runs
  TileBins expected;
  expected.tiles_x = (kWidth + kBinTileSize - 1) / kBinTileSize;
  expected.tiles_y = (kHeight + kBinTileSize - 1) / kBinTileSize;
  expected.offsets.push_back(0);
  for (size_t tile = 0; tile < expected.tileCount(); ++tile) {
    const int tx = int(tile % size_t(expected.tiles_x)), ty = int(tile / size_t(expected.tiles_x));
    const int x0 = tx * kBinTileSize, y0 = ty * kBinTileSize;
    const int x1 = std::min(kWidth, x0 + kBinTileSize) - 1;
    const int y1 = std::min(kHeight, y0 + kBinTileSize) - 1;
    for (size_t i = 0; i < setup.size(); ++i) {
      TileEdges e;
      if (setupTileEdges(setup[i], x0, y0, x1, y1, e)) expected.triangles.push_back(uint32_t(i));
    }
    expected.offsets.push_back(uint32_t(expected.triangles.size()));
  }
  for (int threads : {1, 2, 0}) {
    const ThreadLimit limit(threads);
    const TileBins bins = binTriangles(setup, kWidth, kHeight);
    EXPECT_EQ(bins.offsets, expected.offsets) << threads << " threads";
    EXPECT_EQ(bins.triangles, expected.triangles) << threads << " threads";
  }
}

// Large shadow-volume-like triangles with random depth planes, half counted z-pass and half
// z-fail, some thin and slanted, some covering many whole culling tiles.
ClipTriangles volumeTriangles(int count, int width, int height, uint64_t seed) {
  TestRandom random(seed);
  ClipTriangles tris;
  for (int t = 0; t < count; ++t) {
    const bool big = t % 2 == 0;
    const double cx = random.uniform(-50, width + 50), cy = random.uniform(-50, height + 50);
    const double size = big ? random.uniform(60, 400) : random.uniform(2, 60);
    for (int v = 0; v < 3; ++v) {
      const double angle = random.uniform(0, 6.2832);
      tris.clip.push_back(testing::screenToClip(cx + size * std::cos(angle),
                                                cy + size * std::sin(angle),
                                                random.uniform(0.05, 0.95), width, height));
    }
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2),
             int32_t(random.uniform(1, 4)), t % 4 < 2 ? 0 : kZFail);
  }
  return tris;
}

// The two-level stencil (tile_offsets.h) adds a polygon's contribution once per culling tile it
// covers and passes whole. If this fails, a coarse value went to a tile where some pixel is not
// covered, does not pass the depth rule or shows the background, or was lost at the store: the
// stencil differs from the per-pixel pass for some tile size.
TEST(RasterCullTiles, TwoLevelStencilEqualsPerPixelStencil) {
  constexpr int kWidth = 300, kHeight = 200;
  TestRandom random(5);
  const DepthBuffer depth = randomDepth(kWidth, kHeight, random);
  const ClipTriangles tris = volumeTriangles(400, kWidth, kHeight, 9);
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    for (bool simd : {false, true}) {
      StencilOptions options;
      options.simd = simd;
      options.cull_level = level;
      options.two_level = false;
      Image<int32_t> one(kWidth, kHeight, 0), two(kWidth, kHeight, 0);
      Stats one_stats, two_stats;
      rasterizeStencil(tris, depth, one, one_stats, options);
      options.two_level = true;
      rasterizeStencil(tris, depth, two, two_stats, options);
      ASSERT_TRUE(one == two) << "level " << level << " simd " << simd;
      EXPECT_EQ(one_stats.tiles_accepted, 0u);
      EXPECT_EQ(one_stats.tiles_tested, two_stats.tiles_tested) << "level " << level;
      EXPECT_EQ(one_stats.tiles_culled, two_stats.tiles_culled) << "level " << level;
      // The holes in the depth make a few 256x256-tile bin tiles show background; smaller
      // tiles must find whole ones.
      if (level <= 4) {
        EXPECT_GT(two_stats.tiles_accepted, 0u) << "level " << level;
        EXPECT_LT(two_stats.z_reads, one_stats.z_reads) << "level " << level;
      }
    }
  }
}

}  // namespace test_raster_cull_tiles
}  // namespace penumbra
