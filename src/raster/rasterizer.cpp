#include "raster/rasterizer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <vector>

#include "core/parallel.h"
#include "raster/binning.h"
#include "raster/cull_tiles.h"
#include "raster/delay_stream.h"
#include "raster/depth_pass.h"
#include "raster/fixed_point.h"
#include "raster/plane_depth_range.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"
#include "raster/tile_offsets.h"

namespace penumbra {
namespace {

struct TileCounts {
  KernelCounts kernel;
  CullTally tally;
  uint64_t accepted = 0;  // culling tiles whose polygon went to the coarse level
  uint64_t delay_culled = 0;  // depth pass: pairs the delay stream culled
  uint64_t covered = 0;       // depth pass: pixels with a triangle once the tile is drawn
};

TileBox tileBox(const TileBins& bins, size_t tile, int width, int height) {
  const int tx = int(tile % size_t(bins.tiles_x)), ty = int(tile / size_t(bins.tiles_x));
  const int x0 = tx * kBinTileSize, y0 = ty * kBinTileSize;
  return {x0, y0, std::min(width, x0 + kBinTileSize) - 1, std::min(height, y0 + kBinTileSize) - 1};
}

void sumInto(const std::vector<TileCounts>& tiles, Stats& stats, bool writes_are_stencil) {
  for (const TileCounts& t : tiles) {
    stats.pixels_rasterized += t.kernel.covered;
    stats.z_reads += t.kernel.covered;
    if (writes_are_stencil) stats.stencil_writes += t.kernel.writes;
    stats.tiles_tested += t.tally.tested;
    stats.tiles_culled += t.tally.culled;
    stats.tiles_accepted += t.accepted;
  }
}

// The pixels of the tile's box that a triangle covers (an id other than kNoPrimitive).
uint64_t countCovered(const uint32_t* primitive, const TileBox& box) {
  uint64_t covered = 0;
  for (int y = 0; y <= box.y1 - box.y0; ++y)
    for (int x = 0; x <= box.x1 - box.x0; ++x)
      covered += primitive[y * kBinTileSize + x] != kNoPrimitive;
  return covered;
}

}  // namespace

DepthRuleTiles depthRuleTiles(const SetupTriangle& t, const TileEdges& e, bool zfail, float zmin,
                              float zmax, bool find_all) {
  if (zmax <= 0.0f) return DepthRuleTiles::None;  // only background: nothing to shadow
  const PlaneDepthRange b = planeDepthRange(t, e);
  if (zfail) {
    if (b.lo > double(zmax)) return DepthRuleTiles::None;  // entirely in front of every pixel
    // Behind or at every pixel, none of them background.
    return find_all && zmin > 0.0f && b.hi <= double(zmin) ? DepthRuleTiles::All
                                                           : DepthRuleTiles::Some;
  }
  if (b.hi <= double(zmin)) return DepthRuleTiles::None;  // entirely behind or at every pixel
  // Strictly in front of every pixel, none of them background.
  return find_all && zmin > 0.0f && b.lo > double(zmax) ? DepthRuleTiles::All
                                                        : DepthRuleTiles::Some;
}

namespace {

// rasterizeDepth, and with `ranges` (whose depth image is `depth`) its tile ranges from each
// bin tile's copy before it is stored.
void drawDepth(const ClipTriangles& triangles, Image<float>& depth, Image<uint32_t>& primitive,
               Stats& stats, const DepthPassOptions& options, DepthBuffer* ranges) {
  const int width = depth.width(), height = depth.height();
  PENUMBRA_CHECK(primitive.width() == width && primitive.height() == height,
                 "primitive ids {}x{} do not match depth {}x{}", primitive.width(),
                 primitive.height(), width, height);
  const std::vector<SetupTriangle> setup = setupTriangles(triangles, width, height);
  const TileBins bins = binTriangles(setup, width, height);
  const size_t ring = delayStreamTriangles(options.delay_stream_bytes);
  const bool depth_complexity = options.depth_complexity || ring > 0;
  std::vector<TileCounts> counts(bins.tileCount());
  parallelFor(bins.tileCount(), [&](size_t tile) {
    const TileBox box = tileBox(bins, tile, width, height);
    TileCounts& c = counts[tile];
    // The tile is drawn in a cleared copy of its own, which stays in L1 while every triangle of
    // the tile reads and writes it, then stored once. Drawn in place, the depth kernel waits on
    // the first load of each tile row (raster/tile_copy.h; bench/README.md): a tile's 32 rows
    // lie one image row apart, in as many pages.
    // The tile's rows of depth and ids are written when it is done: asked for now
    // (prefetchRow), they arrive while it is drawn.
    prefetchTileRows(depth, box, true);
    prefetchTileRows(primitive, box, true);
    TileCopy<float> tile_depth(0.0f);
    TileCopy<uint32_t> tile_primitive(kNoPrimitive);
    DepthTarget target{tile_depth.data(), tile_primitive.data(), kBinTileSize};
    target.x0 = box.x0;
    target.y0 = box.y0;
    const uint32_t* first = bins.triangles.data() + bins.offsets[tile];
    const uint32_t* end = bins.triangles.data() + bins.offsets[tile + 1];
    std::optional<DelayStreamTile> delay;
    if (ring > 0) delay.emplace(setup, first, end, box, ring);
    for (const uint32_t* k = first; k != end; ++k) {
      if (k + kBinLookahead < end) prefetchSetupTriangle(setup[k[kBinLookahead]]);
      const SetupTriangle& t = setup[*k];
      TileEdges e;
      ++c.tally.tested;
      if (!setupTileEdges(t, box.x0, box.y0, box.x1, box.y1, e)) {
        ++c.tally.culled;
        continue;
      }
      if (delay && delay->hidden(k, e, tile_depth.data())) {
        ++c.tally.culled;
        ++c.delay_culled;
        continue;
      }
      depthKernel(e, uint32_t(t.payload), target, c.kernel, options.simd);
      if (delay) delay->drawn(e);
    }
    if (depth_complexity) c.covered = countCovered(tile_primitive.data(), box);
    if (ranges != nullptr)
      ranges->setBinTileRanges(tile_depth.data(), kBinTileSize, box.x0, box.y0, box.x1, box.y1);
    tile_depth.storeTo(depth, box);
    tile_primitive.storeTo(primitive, box);
  });
  if (ranges != nullptr) ranges->finishTileRanges();
  sumInto(counts, stats, false);
  stats.triangles += setup.size();
  if (ring > 0) {
    stats.count(kDelayRingTriangles, ring);
    uint64_t culled = 0;
    for (const TileCounts& c : counts) culled += c.delay_culled;
    stats.count(kDelayCulledPairs, culled);
  }
  if (depth_complexity) {
    uint64_t passes = 0, covered = 0;
    for (const TileCounts& c : counts) {
      passes += c.kernel.writes;
      covered += c.covered;
    }
    stats.count(kEyeDepthPasses, passes);
    stats.count(kEyeCoveredPixels, covered);
  }
}

}  // namespace

void rasterizeDepth(const ClipTriangles& triangles, Image<float>& depth,
                    Image<uint32_t>& primitive, Stats& stats, bool simd) {
  drawDepth(triangles, depth, primitive, stats, DepthPassOptions{.simd = simd}, nullptr);
}

void rasterizeDepth(const ClipTriangles& triangles, DepthBuffer& depth,
                    Image<uint32_t>& primitive, Stats& stats, bool simd) {
  rasterizeDepth(triangles, depth, primitive, stats, DepthPassOptions{.simd = simd});
}

void rasterizeDepth(const ClipTriangles& triangles, DepthBuffer& depth,
                    Image<uint32_t>& primitive, Stats& stats, const DepthPassOptions& options) {
  // Sized first: drawDepth checks the sizes, and the tiles' ranges are written in place.
  depth.allocateTileRanges();
  drawDepth(triangles, depth.depth, primitive, stats, options, &depth);
}

void rasterizeStencil(const ClipTriangles& triangles, const DepthBuffer& depth,
                      Image<int32_t>& stencil, Stats& stats, const StencilOptions& options) {
  std::vector<SetupTriangle> setup = setupTriangles(triangles, depth.width(), depth.height());
  stats.triangles += setup.size();
  rasterizeStencil(setup, depth, stencil, stats, options);
}

void rasterizeStencil(const std::vector<SetupTriangle>& setup, const DepthBuffer& depth,
                      Image<int32_t>& stencil, Stats& stats, const StencilOptions& options) {
  const int width = depth.width(), height = depth.height();
  PENUMBRA_CHECK(stencil.width() == width && stencil.height() == height,
                 "stencil {}x{} does not match depth {}x{}", stencil.width(), stencil.height(),
                 width, height);
  PENUMBRA_DCHECK(std::all_of(stencil.data(), stencil.data() + stencil.size(),
                              [](int32_t s) { return s == 0; }));
  const TileBins bins = binTriangles(setup, width, height);
  std::vector<TileCounts> counts(bins.tileCount());
  for (TileCounts& c : counts) c.tally.culled_layer = options.culled_layer;
  parallelFor(bins.tileCount(), [&](size_t tile) {
    const TileBox box = tileBox(bins, tile, width, height);
    TileCounts& c = counts[tile];
    if (bins.offsets[tile] == bins.offsets[tile + 1]) return;
    // As rasterizeDepth: the tile's depth and stencil in contiguous copies of their own. In
    // place, a tile's rows are one image row apart, which at 1920 (or 640) pixels is a multiple
    // of 512 bytes: its 32 rows of depth and stencil fall into a sixteenth of the L1 cache sets.
    // The tile's stencil rows are written when it is done: asked for now (prefetchRow), they
    // arrive while it is drawn.
    prefetchTileRows(stencil, box, true);
    TileCopy<float> tile_depth(depth.depth, box);
    TileCopy<int32_t> tile_stencil(0);  // the caller cleared the stencil: nothing to read
    StencilTarget target{tile_depth.data(), tile_stencil.data(), kBinTileSize};
    target.x0 = box.x0;
    target.y0 = box.y0;
    // The primitive ids, copied the first time a polygon with owners reaches the tile.
    std::optional<TileCopy<uint32_t>> tile_primitive;
    // Two-level stencil: a polygon that covers a whole culling tile and passes the depth rule
    // at all of its pixels adds its contribution to the tile's coarse cell instead.
    TileOffsets coarse(options.cull_level);
    constexpr int kDraw = 1, kWhole = 2;
    const bool two_level = options.tile_culling && options.two_level;
    const uint32_t end = bins.offsets[tile + 1];
    for (uint32_t k = bins.offsets[tile]; k < end; ++k) {
      if (k + kBinLookahead < end)
        prefetchSetupTriangle(setup[bins.triangles[k + kBinLookahead]]);
      const SetupTriangle& t = setup[bins.triangles[k]];
      TileEdges e;
      if (!setupTileRect(t, box.x0, box.y0, box.x1, box.y1, e)) continue;
      const bool zfail = (t.flags & kZFail) != 0;
      const int32_t contribution = t.payload * t.facing * (zfail ? -1 : 1);
      const DepthRule rule = zfail ? DepthRule::NotCloser : DepthRule::Closer;
      const StencilOwners owners = options.primitive
                                       ? StencilOwners{t.owners[0], t.owners[1]}
                                       : StencilOwners{};
      if (owners.any() && !tile_primitive) {
        tile_primitive.emplace(*options.primitive, box);
        target.primitive = tile_primitive->data();
      }
      forEachCullRect(
          t, e, depth, options.cull_level,
          [&](const TileEdges& sub, float zmin, float zmax) {
            if (!options.tile_culling) return kDraw;
            switch (depthRuleTiles(t, sub, zfail, zmin, zmax, two_level)) {
              case DepthRuleTiles::None: return 0;
              case DepthRuleTiles::Some: return kDraw;
              case DepthRuleTiles::All: return kDraw | kWhole;
            }
            return kDraw;
          },
          [&](const TileEdges& rect, int code) {
            if (code & kWhole)
              coarse.add(rect, contribution);
            else
              stencilKernel(rect, contribution, rule, target, c.kernel, options.simd,
                            owners);
          },
          c.tally, kWhole);
    }
    coarse.applyTo(
        tile_stencil.data(), box, [](int32_t& s, int32_t sum) { s += sum; }, c.kernel.writes,
        c.accepted);
    tile_stencil.storeTo(stencil, box);
  });
  sumInto(counts, stats, true);
}

int32_t stencilContributionAt(const SetupTriangle& t, int x, int y, const DepthBuffer& depth,
                              const Image<uint32_t>* primitive) {
  const int tx0 = x & ~(kBinTileSize - 1), ty0 = y & ~(kBinTileSize - 1);
  const int tx1 = std::min(depth.width(), tx0 + kBinTileSize) - 1;
  const int ty1 = std::min(depth.height(), ty0 + kBinTileSize) - 1;
  TileEdges e;
  if (!setupTileRect(t, tx0, ty0, tx1, ty1, e)) return 0;
  if (x < e.x0 || x > e.x1 || y < e.y0 || y > e.y1) return 0;
  if (!setupRectEdges(t, e)) return 0;
  const int rx = x - e.tx0, ry = y - e.ty0;
  for (int i = 0; i < 3; ++i)
    if ((e.e0[i] + e.dy[i] * ry) + e.dx[i] * rx < 0) return 0;
  const float stored = depth.depth.at(x, y);
  const float d = triangleDepthAt(e, x, y);
  const bool zfail = (t.flags & kZFail) != 0;
  const bool pass = zfail ? d <= stored : d > stored;
  const bool own = primitive != nullptr &&
                   (primitive->at(x, y) == t.owners[0] || primitive->at(x, y) == t.owners[1]);
  if (!(stored > 0.0f) || !pass || own) return 0;
  return t.payload * t.facing * (zfail ? -1 : 1);
}

void forEachBinTile(const ClipTriangles& triangles, int width, int height,
                    const std::function<bool(const SetupTriangle&)>& keep,
                    const std::function<void(const TileTriangles&)>& visit, Stats& stats) {
  std::vector<SetupTriangle> setup = setupTriangles(triangles, width, height);
  stats.triangles += setup.size();
  std::erase_if(setup, [&](const SetupTriangle& t) { return !keep(t); });
  forEachBinTile(setup, width, height, visit);
}

void forEachBinTile(const std::vector<SetupTriangle>& setup, int width, int height,
                    const std::function<void(const TileTriangles&)>& visit) {
  const TileBins bins = binTriangles(setup, width, height);
  parallelFor(bins.tileCount(), [&](size_t tile) {
    if (bins.offsets[tile] == bins.offsets[tile + 1]) return;
    visit(TileTriangles(tile, tileBox(bins, tile, width, height), setup,
                        bins.triangles.data() + bins.offsets[tile],
                        bins.triangles.data() + bins.offsets[tile + 1]));
  });
}

}  // namespace penumbra
