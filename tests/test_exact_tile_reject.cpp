// The exact technique bins its potential edges into screen tiles with the tile form of the
// per-pixel quick reject (edge_screen_test.h: edgeTileCandidates): each tile's box of pixel
// centres and depth range put into the edge's region planes and triangle planes, SIMD over the
// tiles of a box's rows with a scalar twin. Two things must hold. The twins agree tile for tile
// (and the pixel reject's twins pixel for pixel), or `exact`'s work (and, through a wrong cull,
// its image) would depend on the CPU's vector width or --scalar. And a tile is kept whenever
// one of its pixels is kept by the pixel reject (edgeCandidates) with an offset up to the
// tiles': a tile culled with a candidate pixel in it would drop that pixel's edge, and the
// pixel would be counted as lit where the oracle finds it shadowed. Both hold with and without
// the tiles' depth parts (EdgeTileParts), which cull more.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "eye_frame_util.h"
#include "raster/depth_buffer.h"
#include "scene/builtin_scenes.h"
#include "shadows/stages/light_sampling/ray_origin.h"
#include "shadows/stages/potential_edges/edge_bins.h"
#include "shadows/stages/potential_edges/edge_screen_test.h"

namespace penumbra {
namespace test_exact_tile_reject {

constexpr int kTile = 8;

struct Random {
  std::mt19937_64 engine{19840101};
  float uniform(float lo, float hi) {
    return lo + (hi - lo) * float(double(engine() >> 11) * 0x1.0p-53);
  }
  bool coin() { return (engine() & 1) != 0; }
  int below(int n) { return int(engine() % uint64_t(n)); }
};

// A random edge test in screen form: planes whose zero sets cross the image (so that tiles fall
// on both sides), rounding margins from 0 up to a few pixels' worth, 0 to 4 triangles, some
// cutting the light.
EdgeScreenTest randomTest(Random& r, int width, int height) {
  EdgeScreenTest t;
  auto plane = [&](float out[4]) {
    out[0] = r.uniform(-1.0f, 1.0f);
    out[1] = r.uniform(-1.0f, 1.0f);
    out[2] = r.uniform(-300.0f, 300.0f);
    // Zero at a random point of the image and depth.
    const float x = r.uniform(0.0f, float(width)), y = r.uniform(0.0f, float(height));
    const float z = r.uniform(0.0f, 1.0f);
    out[3] = -((out[0] * x + out[1] * y) + out[2] * z);
    if (r.below(8) == 0) out[r.below(3)] = 0.0f;  // a plane parallel to an axis
  };
  t.region_count = r.below(kMaxRegionPlanes + 1);
  for (int k = 0; k < t.region_count; ++k) {
    plane(t.region[k]);
    t.region_margin[k] = r.coin() ? 0.0f : r.uniform(0.0f, 3.0f);
  }
  t.triangle_count = r.below(5);
  for (int k = 0; k < t.triangle_count; ++k) {
    plane(t.triangle[k]);
    t.triangle_margin[k] = r.coin() ? 0.0f : r.uniform(0.0f, 3.0f);
    t.light_above[k] = r.coin();
    t.weight[k] = r.coin() ? 1 : -1;
    t.cuts[k] = r.below(6) == 0;
    t.any_cuts |= t.cuts[k];
    for (int j = 0; j < 3; ++j) t.opposite[k][j] = r.uniform(-2.0f, 2.0f);
    t.cut_extent[k] = r.uniform(1.0f, 4.0f);
  }
  for (int e = 0; e < 2; ++e)
    for (int j = 0; j < 3; ++j) t.ends[e][j] = r.uniform(-2.0f, 2.0f);
  return t;
}

// A depth image with smooth patches, steps, background (0) and exact ties to plane values.
std::vector<float> randomDepth(Random& r, int width, int height) {
  std::vector<float> depth(size_t(width) * size_t(height));
  const float base = r.uniform(0.05f, 0.9f), gx = r.uniform(-1e-3f, 1e-3f),
              gy = r.uniform(-1e-3f, 1e-3f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float z = base + gx * float(x) + gy * float(y);
      if (((x / 11) + (y / 7)) % 5 == 0) z += r.uniform(-0.05f, 0.05f);  // steps
      if (((x / 5) + (y / 3)) % 7 == 0) z *= 0.3f;  // a far surface behind an edge
      if ((x + 3 * y) % 23 == 0) z = 0.0f;                               // background
      depth[size_t(y) * size_t(width) + size_t(x)] = std::clamp(z, 0.0f, 1.0f);
    }
  return depth;
}

TEST(ExactTileReject, TwinsAgreeAndEveryTileWithACandidatePixelIsKept) {
  Random r;
  size_t tiles_tested = 0, tiles_kept = 0, candidate_pixels = 0, pixel_twin_blocks = 0;
  size_t parts_dropped = 0;
  // Widths whose last tile is partial, and rows longer than one vector of tiles.
  for (const int width : {37, 64, 203}) {
    const int height = 2 * kTile + 5;
    const int columns = (width + kTile - 1) / kTile, rows = (height + kTile - 1) / kTile;
    for (int trial = 0; trial < 60; ++trial) {
      const std::vector<float> depth = randomDepth(r, width, height);
      // Per-tile depth range of the covered pixels (the background's 0 included, as
      // DepthBuffer's pyramid has it: a tile with background reaches z = 0).
      // Padded as edgeTileCandidates requires (kTileBoxPadding).
      std::vector<float> zmin(size_t(columns) * size_t(rows) + kTileBoxPadding, 1.0f),
          zmax(size_t(columns) * size_t(rows) + kTileBoxPadding, 0.0f);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const size_t t = size_t(y / kTile) * size_t(columns) + size_t(x / kTile);
          const float z = depth[size_t(y) * size_t(width) + size_t(x)];
          zmin[t] = std::min(zmin[t], z);
          zmax[t] = std::max(zmax[t], z);
        }
      // The same depths as a depth buffer, for the tiles' depth parts.
      DepthBuffer buffer;
      buffer.depth.resizeForOverwrite(width, height);
      std::copy(depth.begin(), depth.end(), buffer.depth.data());
      buffer.buildTileRanges();
      const TileDepthParts depth_parts = tileDepthParts(buffer, 3);
      const EdgeTileParts parts = depth_parts.view();
      for (int e = 0; e < 6; ++e) {
        const EdgeScreenTest test = randomTest(r, width, height);
        for (int box_index = 0; box_index < 4; ++box_index) {
          // A random box of tiles, or the whole grid.
          EdgeTileBox box;
          box.zmin = zmin.data();
          box.zmax = zmax.data();
          box.columns = columns;
          box.tx0 = r.below(columns);
          box.tx1 = box.tx0 + r.below(columns - box.tx0);
          box.ty0 = r.below(rows);
          box.ty1 = box.ty0 + r.below(rows - box.ty0);
          if (r.coin()) box.tx0 = 0, box.tx1 = columns - 1, box.ty0 = 0, box.ty1 = rows - 1;
          box.size = kTile;
          box.width = width;
          box.height = height;
          // The largest offset a pixel may have (0 sometimes: the rounding margins alone).
          box.offset = r.below(4) == 0 ? 0.0f : r.uniform(0.0f, 2.0f);
          const size_t room = size_t(columns) * size_t(rows);
          // With the depth parts half the time; they only ever drop tiles.
          if (r.coin()) {
            std::vector<uint32_t> whole(room);
            int whole_tested = 0;
            const int whole_count = edgeTileCandidatesScalar(test, box, whole.data(), whole_tested);
            box.parts = &parts;
            std::vector<uint32_t> split(room);
            int split_tested = 0;
            const int split_count = edgeTileCandidatesScalar(test, box, split.data(), split_tested);
            ASSERT_LE(split_count, whole_count);
            ASSERT_EQ(split_tested, whole_tested);
            parts_dropped += size_t(whole_count - split_count);
          }
          std::vector<uint32_t> simd_kept(room), scalar_kept(room);
          int simd_tested = -1, scalar_tested = -2;
          const int simd_count =
              edgeTileCandidates(test, box, simd_kept.data(), simd_tested, true);
          const int scalar_count =
              edgeTileCandidatesScalar(test, box, scalar_kept.data(), scalar_tested);
          ASSERT_EQ(simd_count, scalar_count) << "width " << width << " box " << box_index;
          ASSERT_EQ(simd_tested, scalar_tested);
          simd_kept.resize(size_t(simd_count));
          scalar_kept.resize(size_t(scalar_count));
          ASSERT_EQ(simd_kept, scalar_kept);
          tiles_tested += size_t(scalar_tested);
          tiles_kept += size_t(scalar_count);
          // Every tile of the box with a candidate pixel must be among the kept ones.
          for (int ty = box.ty0; ty <= box.ty1; ++ty) {
            for (int tx = box.tx0; tx <= box.tx1; ++tx) {
              PixelBlock block;
              block.active = 0;
              block.has_q = false;
              int i = 0;
              for (int y = ty * kTile; y < std::min(ty * kTile + kTile, height); ++y)
                for (int x = tx * kTile; x < std::min(tx * kTile + kTile, width); ++x, ++i) {
                  block.sx[i] = float(x) + 0.5f;
                  block.sy[i] = float(y) + 0.5f;
                  block.z[i] = depth[size_t(y) * size_t(width) + size_t(x)];
                  block.qx[i] = block.qy[i] = block.qz[i] = block.reach[i] = block.slack[i] = 0;
                  // A pixel's offset is at most the tiles': the shaded point known (smaller) or
                  // not (the tiles').
                  block.offset[i] = r.coin() ? box.offset : r.uniform(0.0f, box.offset);
                  if (block.z[i] > 0.0f) block.active |= uint64_t(1) << i;
                }
              const uint64_t candidates = edgeCandidatesScalar(test, block);
              ASSERT_EQ(edgeCandidates(test, block, true), candidates)
                  << "pixel twins differ in tile (" << tx << ", " << ty << ")";
              // With q known, the cutting triangles' proof runs too (the twins must agree there;
              // a q can only remove candidates, so the tile property is checked without it).
              PixelBlock with_q = block;
              with_q.has_q = true;
              for (int k = 0; k < kBlockPixels; ++k) {
                with_q.qx[k] = r.uniform(-3.0f, 3.0f);
                with_q.qy[k] = r.uniform(-3.0f, 3.0f);
                with_q.qz[k] = r.uniform(-3.0f, 3.0f);
                with_q.reach[k] = r.uniform(0.0f, 1.0f);
                with_q.slack[k] = r.uniform(0.0f, 0.1f);
              }
              ASSERT_EQ(edgeCandidates(test, with_q, true), edgeCandidatesScalar(test, with_q));
              pixel_twin_blocks += 1;
              if (candidates == 0) continue;
              candidate_pixels += size_t(__builtin_popcountll(candidates));
              const uint32_t index = uint32_t(ty * columns + tx);
              EXPECT_TRUE(std::find(scalar_kept.begin(), scalar_kept.end(), index) !=
                          scalar_kept.end())
                  << "tile (" << tx << ", " << ty << ") culled with "
                  << __builtin_popcountll(candidates) << " candidate pixels, width " << width;
            }
          }
        }
      }
    }
  }
  std::printf(
      "[ exact    ] tile reject: %zu tiles tested, %zu kept, %zu candidate pixels, %zu blocks "
      "through both pixel twins, %zu tiles dropped by the depth parts\n",
      tiles_tested, tiles_kept, candidate_pixels, pixel_twin_blocks, parts_dropped);
  // Both outcomes were exercised.
  EXPECT_GT(tiles_kept, tiles_tested / 20);
  EXPECT_LT(tiles_kept, tiles_tested - tiles_tested / 20);
  EXPECT_GT(candidate_pixels, 1000u);
  EXPECT_GT(parts_dropped, 100u);
}

}  // namespace test_exact_tile_reject
}  // namespace penumbra

namespace penumbra {
namespace test_exact_tile_reject {

// binEdges tests a region's coarse tiles (2^step x 2^step bin tiles, their pixel boxes and depth
// parts hulled) before its bin tiles, and skips the bin tiles of the coarse tiles it culls. If a
// coarse tile were culled while one of its bin tiles would be kept (a hull that does not hold a
// bin tile's box or depth part, a float evaluation that is not monotone), that tile would lose
// the edge: its pixels would count the samples behind the edge as lit where the oracle finds
// them shadowed. So the bins, and the work counters the frame digests record, must be exactly
// those of the flat scan, on scenes with depth steps at tile borders, background between
// objects and several occluders behind one another (fractal), at bin tiles of 4, 8 and 16 pixels
// and coarse steps 1 to 3, SIMD and scalar.
TEST(ExactTileReject, CoarseTilesKeepTheFlatScansBins) {
  size_t compared_pairs = 0, culled = 0;
  for (const char* name : {"spheres", "columns", "fractal", "year2002"}) {
    Scene scene = builtinScene(name);
    // Non-square, and not a multiple of any tile size: partial tiles and coarse tiles.
    const testing::EyeFrame frame = testing::makeEyeFrame(std::move(scene), 203, 131);
    for (Light light : frame.scene.lights) {
      if (!(light.radius > 0.0f)) light.radius = 0.05f * frame.scene.bounds().radius();
      const PotentialEdges edges = potentialEdges(frame.scene, light);
      for (const int level : {2, 3, 4}) {
        for (const bool simd : {true, false}) {
          const EdgeBins flat = binEdges(edges, light, frame.view, frame.eye.depth, level,
                                         kMaxOriginOffsetFootprints, frame.scene.bounds(), simd, 0);
          // Every coarse step at the default bin tiles, the default step at the others (the
          // test runs under the sanitizers too).
          for (const int step : level == 3 ? std::vector<int>{1, 2, 3} : std::vector<int>{2}) {
            const EdgeBins coarse =
                binEdges(edges, light, frame.view, frame.eye.depth, level,
                         kMaxOriginOffsetFootprints, frame.scene.bounds(), simd, step);
            const std::string where = std::string(name) + " level " + std::to_string(level) +
                                      " step " + std::to_string(step) +
                                      (simd ? " simd" : " scalar");
            ASSERT_EQ(coarse.begin, flat.begin) << where;
            ASSERT_EQ(coarse.edges, flat.edges) << where;
            ASSERT_EQ(coarse.cutting_begin, flat.cutting_begin) << where;
            ASSERT_EQ(coarse.cutting, flat.cutting) << where;
            ASSERT_EQ(coarse.tiles_tested, flat.tiles_tested) << where;
            ASSERT_EQ(coarse.tiles_culled, flat.tiles_culled) << where;
          }
          compared_pairs += flat.edges.size() + flat.cutting.size();
          culled += flat.tiles_culled;
        }
      }
    }
  }
  // The comparison saw real work: edges binned to tiles and tiles culled.
  EXPECT_GT(compared_pairs, 10000u);
  EXPECT_GT(culled, 10000u);
}

}  // namespace test_exact_tile_reject
}  // namespace penumbra
