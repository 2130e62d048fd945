#pragma once
// Tiles for z-min/z-max occlusion culling (2004 paper, section 4), of any size 2^n, n = 1..8,
// walked inside the bin tiles that own the pixels (fixed_point.h: kBinTileSize).
#include <algorithm>
#include <cstdint>

#include "raster/depth_buffer.h"
#include "raster/fixed_point.h"
#include "raster/tile_kernels.h"

namespace penumbra {

// Culling tiles visited and culled, the tiles_tested / tiles_culled counters.
struct CullTally {
  uint64_t tested = 0, culled = 0;
  // When set (a debug layer, kCulledTilesLayer in shadows/technique.h): 1 is added to every
  // pixel of each culled tile. A bin tile's walk writes its own pixels only, so the bin tiles'
  // workers may share it.
  Image<float>* culled_layer = nullptr;
};

// Adds 1 to the culled layer over the culling tiles of level `level` that the rect of `e`
// reaches, within its bin tile and the image.
inline void markCulledTiles(const CullTally& tally, const TileEdges& e, int level) {
  if (tally.culled_layer == nullptr) return;
  Image<float>& layer = *tally.culled_layer;
  const int size = 1 << level;
  const int x0 = std::max(e.tx0, (e.x0 >> level) << level);
  const int y0 = std::max(e.ty0, (e.y0 >> level) << level);
  const int x1 = std::min({((e.x1 >> level) << level) + size - 1, e.tx0 + kBinTileSize - 1,
                           layer.width() - 1});
  const int y1 = std::min({((e.y1 >> level) << level) + size - 1, e.ty0 + kBinTileSize - 1,
                           layer.height() - 1});
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) layer.at(x, y) += 1.0f;
}

// True when `rect` (set up by setupRectEdges) is its whole cell and every pixel of it is inside
// the triangle. A cell is a culling tile of level `level` within the rect's bin tile (a culling
// tile larger than the bin tile has the bin tile as its cell), clipped to the image: passes
// keep one coarse value per cell (tile_offsets.h). The edges are linear, so each is smallest at
// a corner of the rect; the values are the kernels' own int32 edge values (fixed_point.h), so
// "covered" means exactly what the kernels' inside test means. A folded edge (e0 = dx = dy = 0)
// holds everywhere.
inline bool coversCell(const TileEdges& rect, int level, int width, int height) {
  const int size = 1 << std::min(level, kBinTileLevel);
  const int x0 = std::max(rect.tx0, (rect.x0 >> level) << level);
  const int y0 = std::max(rect.ty0, (rect.y0 >> level) << level);
  if (rect.x0 != x0 || rect.y0 != y0 ||
      rect.x1 != std::min({x0 + size - 1, rect.tx0 + kBinTileSize - 1, width - 1}) ||
      rect.y1 != std::min({y0 + size - 1, rect.ty0 + kBinTileSize - 1, height - 1}))
    return false;
  const int32_t rx0 = rect.x0 - rect.tx0, rx1 = rect.x1 - rect.tx0;
  const int32_t ry0 = rect.y0 - rect.ty0, ry1 = rect.y1 - rect.ty0;
  for (int i = 0; i < 3; ++i) {
    const int32_t low = rect.e0[i] + std::min(rect.dx[i] * rx0, rect.dx[i] * rx1) +
                        std::min(rect.dy[i] * ry0, rect.dy[i] * ry1);
    if (low < 0) return false;
  }
  return true;
}

namespace cull_detail {

// A rectangle of culling tiles with one code, not drawn yet: columns [cx0, cx1] from row cy0 on.
struct PendingRun {
  int cx0, cx1, cy0, code;
};

// Row cy's runs (`next`, by column) after the rows before: a run identical to one of the
// previous row's pending rectangles extends it; pending rectangles that no run extends are
// complete (flush(p, cy - 1)). The runs are then the pending rectangles.
template <class Flush>
inline void extendPendingRuns(PendingRun* pending, int& pending_count, PendingRun* next,
                              int next_count, int cy, Flush& flush) {
  int k = 0;
  for (int i = 0; i < pending_count; ++i) {
    const PendingRun& p = pending[i];
    while (k < next_count && next[k].cx0 < p.cx0) ++k;
    if (k < next_count && next[k].cx0 == p.cx0 && next[k].cx1 == p.cx1 &&
        next[k].code == p.code) {
      next[k].cy0 = p.cy0;
    } else {
      flush(p, cy - 1);
    }
  }
  std::copy(next, next + next_count, pending);
  pending_count = next_count;
}

}  // namespace cull_detail

// Walks the culling tiles of level `level` that the rect of `e` touches (a culling tile at least
// as large as the bin tile contains the rect whole). `e` comes from setupTileRect: the triangle's
// edges are set up (setupRectEdges) only once a tile of the rect survives the pre-test below.
// The binner hands out only pairs whose edges meet the rect (binning.cpp), so the tallies do not
// depend on whether the edges were set up. decide(sub, zmin, zmax), with
// `sub` restricted to that culling tile's pixels and [zmin, zmax] its stored depth range, is the
// papers' per-tile test: it returns a code, 0 to cull the tile, else what to draw there (for
// passes with two parts, a bit per part). Then draw(rect, code) runs once per rectangle of
// adjacent tiles with the same code: runs along a row of culling tiles, extended down while the
// next row has the same run. Each pixel is drawn once with its tile's code, so the buffers and
// counts are those of a per-tile walk, but a bin tile with nothing culled is one kernel call
// instead of up to (32 / 2^level)^2 calls on rows shorter than a SIMD vector (the soft frame's
// times with and without the merging are in bench/README.md).
//
// `decide` must be monotonic: a rect inside another, with a depth range inside the other's,
// culls at least the parts the larger one culls. The papers' tests are (a plane's maximum over a
// smaller box is smaller; the z-range rejects compare with a narrower range). So tiles smaller than
// the bin tile are first decided together on the whole rect with the bin tile's range: when that
// culls everything, each of them would have been culled, and they are tallied so without a test
// each (most pairs of a long shadow quad or wedge face and a tile are culled whole).
//
// `whole_bits` are bits of a code that hold only where the triangle covers its culling tile's
// cell (coversCell above) entirely: the walk clears them elsewhere before drawing, so that a
// pass can say "this part passes the depth test at every pixel of the tile" from the depth
// range alone and get the bit only where it may skip the pixels (two-level stencil,
// tile_offsets.h).
template <class Decide, class Draw>
void forEachCullRect(const SetupTriangle& t, TileEdges& e, const DepthBuffer& depth, int level,
                     Decide&& decide, Draw&& draw, CullTally& tally, int whole_bits = 0) {
  const uint64_t tiles = uint64_t((e.x1 >> level) - (e.x0 >> level) + 1) *
                         uint64_t((e.y1 >> level) - (e.y0 >> level) + 1);
  auto cullAll = [&] {
    tally.tested += tiles;
    tally.culled += tiles;
    markCulledTiles(tally, e, level);
  };
  auto keepWhole = [&](const TileEdges& sub, int code) {
    if ((code & whole_bits) == 0 || coversCell(sub, level, depth.width(), depth.height()))
      return code;
    return code & ~whole_bits;
  };
  if (level >= kBinTileLevel) {
    const TileDepthRange& range = depth.tileRange(level);
    const int cx = e.x0 >> level, cy = e.y0 >> level;
    const int code = decide(e, range.zmin.at(cx, cy), range.zmax.at(cx, cy));
    if (code == 0) return cullAll();
    if (!setupRectEdges(t, e)) return;  // not handed out by the binner
    ++tally.tested;
    draw(e, keepWhole(e, code));
    return;
  }
  const TileDepthRange& range = depth.tileRange(level);
  const TileDepthRange& bin = depth.tileRange(kBinTileLevel);
  const int bx = e.x0 >> kBinTileLevel, by = e.y0 >> kBinTileLevel;
  if (decide(e, bin.zmin.at(bx, by), bin.zmax.at(bx, by)) == 0) return cullAll();
  if (!setupRectEdges(t, e)) return;  // not handed out by the binner
  const int size = 1 << level;
  const int cx_first = e.x0 >> level, cx_last = e.x1 >> level;
  using cull_detail::PendingRun;
  // At most kBinTileSize / 2 culling tiles per row, so at most that many runs.
  PendingRun pending[kBinTileSize / 2], next[kBinTileSize / 2];
  int pending_count = 0;
  auto flush = [&](const PendingRun& p, int cy1) {
    TileEdges rect = e;
    rect.x0 = std::max(e.x0, p.cx0 * size);
    rect.x1 = std::min(e.x1, p.cx1 * size + size - 1);
    rect.y0 = std::max(e.y0, p.cy0 * size);
    rect.y1 = std::min(e.y1, cy1 * size + size - 1);
    draw(rect, p.code);
  };
  for (int cy = e.y0 >> level; cy <= (e.y1 >> level); ++cy) {
    int next_count = 0;
    int run_code = 0;
    for (int cx = cx_first; cx <= cx_last + 1; ++cx) {
      int code = 0;
      if (cx <= cx_last) {
        TileEdges sub = e;
        sub.x0 = std::max(e.x0, cx * size);
        sub.y0 = std::max(e.y0, cy * size);
        sub.x1 = std::min(e.x1, cx * size + size - 1);
        sub.y1 = std::min(e.y1, cy * size + size - 1);
        code = decide(sub, range.zmin.at(cx, cy), range.zmax.at(cx, cy));
        ++tally.tested;
        tally.culled += code == 0;
        if (code == 0) markCulledTiles(tally, sub, level);
        if (code != 0) code = keepWhole(sub, code);
      }
      if (code == run_code && cx <= cx_last) {
        if (code != 0) next[next_count - 1].cx1 = cx;
        continue;
      }
      run_code = code;
      if (code != 0) next[next_count++] = {cx, cx, cy, code};
    }
    cull_detail::extendPendingRuns(pending, pending_count, next, next_count, cy, flush);
  }
  for (int i = 0; i < pending_count; ++i) flush(pending[i], e.y1 >> level);
}

// Which pixels of the rect can pass the triangle's depth rule against a tile whose stored
// depths lie in [zmin, zmax] (reversed-Z): z-pass counts where the triangle is in front, so
// None when it is behind or at the tile's farthest depth (the papers' z-max), All when it is
// in front of the tile's nearest (the papers' z-min); z-fail counts behind or at, so None when
// it is in front of the nearest, All when behind or at the farthest. The triangle's depth over
// the rect is bounded by its plane at the rect's corners, widened by the float error of the
// kernels' evaluation, so neither answer changes a pixel. Tiles of only background are None
// (nothing to shadow); All also needs every pixel to have a surface (zmin > 0), and is only
// looked for when `find_all` (it needs z-min, which only full culling has).
enum class DepthRuleTiles : uint8_t { None, Some, All };
DepthRuleTiles depthRuleTiles(const SetupTriangle& t, const TileEdges& e, bool zfail, float zmin,
                              float zmax, bool find_all);

}  // namespace penumbra
