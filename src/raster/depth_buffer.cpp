#include "raster/depth_buffer.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"
#include "raster/fixed_point.h"

namespace penumbra {
namespace {

// `b < a ? b : a` is std::min's choice, written so the compiler turns whole rows into packed
// min/max instructions (std::min's reference return keeps some compilers from it). Depth holds no
// NaN, so the order of the terms cannot change a result.
inline float minOf(float a, float b) { return b < a ? b : a; }
inline float maxOf(float a, float b) { return a < b ? b : a; }

// One output row of a 2x2 reduction: out[i] over columns 2i and 2i + 1 of rows `a` and `b`
// (`n` entries each; an odd last column stands alone, as does an odd last row: b == a).
template <bool kMin>
void reducePairs(const float* a, const float* b, int n, float* out) {
  const int pairs = n / 2;
  for (int i = 0; i < pairs; ++i) {
    if constexpr (kMin) {
      out[i] = minOf(minOf(a[2 * i], b[2 * i]), minOf(a[2 * i + 1], b[2 * i + 1]));
    } else {
      out[i] = maxOf(maxOf(a[2 * i], b[2 * i]), maxOf(a[2 * i + 1], b[2 * i + 1]));
    }
  }
  if (n & 1) out[pairs] = kMin ? minOf(a[n - 1], b[n - 1]) : maxOf(a[n - 1], b[n - 1]);
}

// Level 1 row: min and max of the same pixels in one pass, so the depth rows are read once.
void reducePixelPairs(const float* a, const float* b, int n, float* out_min, float* out_max) {
  const int pairs = n / 2;
  for (int i = 0; i < pairs; ++i) {
    const float a0 = a[2 * i], a1 = a[2 * i + 1], b0 = b[2 * i], b1 = b[2 * i + 1];
    out_min[i] = minOf(minOf(a0, b0), minOf(a1, b1));
    out_max[i] = maxOf(maxOf(a0, b0), maxOf(a1, b1));
  }
  if (n & 1) {
    out_min[pairs] = minOf(a[n - 1], b[n - 1]);
    out_max[pairs] = maxOf(a[n - 1], b[n - 1]);
  }
}

// Builds level `level` rows [row_begin, row_end) from the level below (or from the pixels).
void reduceRows(const Image<float>& below_min, const Image<float>& below_max, TileDepthRange& r,
                int row_begin, int row_end) {
  const int n = below_min.width(), below_rows = below_min.height();
  for (int ty = row_begin; ty < row_end; ++ty) {
    const int y0 = 2 * ty, y1 = std::min(2 * ty + 1, below_rows - 1);
    if (&below_min == &below_max) {
      reducePixelPairs(below_min.row(y0), below_min.row(y1), n, r.zmin.row(ty), r.zmax.row(ty));
    } else {
      reducePairs<true>(below_min.row(y0), below_min.row(y1), n, r.zmin.row(ty));
      reducePairs<false>(below_max.row(y0), below_max.row(y1), n, r.zmax.row(ty));
    }
  }
}

}  // namespace

// Level 1 from the pixels, every further level from the one below (a min/max pyramid), each
// level's tiles covering only pixels inside the image. Bands of 2^kBandLevel pixel rows are
// independent up to level kBandLevel, so each worker builds levels 1..kBandLevel of its band
// while the rows are in its cache; the few rows of the levels above follow serially.
void DepthBuffer::buildTileRanges() {
  constexpr int kBandLevel = 6;
  const int h = depth.height();
  allocateTileRanges();
  const int bands = (h + (1 << kBandLevel) - 1) >> kBandLevel;
  parallelFor(size_t(bands), [&](size_t band) {
    for (int level = kMinTileLevel; level <= kBandLevel; ++level) {
      TileDepthRange& r = tiles[level];
      const int row_begin = int(band << (kBandLevel - level));
      const int row_end = std::min(r.zmin.height(), int((band + 1) << (kBandLevel - level)));
      if (level == kMinTileLevel) {
        reduceRows(depth, depth, r, row_begin, row_end);
      } else {
        reduceRows(tiles[level - 1].zmin, tiles[level - 1].zmax, r, row_begin, row_end);
      }
    }
  });
  for (int level = kBandLevel + 1; level <= kMaxTileLevel; ++level) {
    reduceRows(tiles[level - 1].zmin, tiles[level - 1].zmax, tiles[level], 0,
               tiles[level].zmin.height());
  }
}

void DepthBuffer::allocateTileRanges() {
  const int w = depth.width(), h = depth.height();
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    TileDepthRange& r = tiles[level];
    r.level = level;
    const int size = 1 << level;
    const int tw = (w + size - 1) / size, th = (h + size - 1) / size;
    r.zmin.resizeForOverwrite(tw, th);
    r.zmax.resizeForOverwrite(tw, th);
  }
}

void DepthBuffer::setBinTileRanges(const float* pixels, int stride, int x0, int y0, int x1,
                                   int y1) {
  static_assert(kBinTileLevel == 5, "setBinTileRanges fills levels 1..5 of a 32x32 tile");
  PENUMBRA_DCHECK(x0 % kBinTileSize == 0 && y0 % kBinTileSize == 0);
  // Level 1 from the pixels, each further level from the one below, over the tiles holding a
  // pixel of the box (a tile cut by the image's edge takes only its pixels inside, as
  // buildTileRanges' odd last columns and rows). Each level's rows are written straight into
  // the level's images: the bin tile's tiles there are its own.
  int cols = x1 - x0 + 1, rows = y1 - y0 + 1;  // of the level below
  for (int level = kMinTileLevel; level <= kBinTileLevel; ++level) {
    TileDepthRange& r = tiles[level];
    const int out_cols = (cols + 1) / 2, out_rows = (rows + 1) / 2;
    const int tx0 = x0 >> level, ty0 = y0 >> level;
    for (int ty = 0; ty < out_rows; ++ty) {
      const int ya = 2 * ty, yb = std::min(2 * ty + 1, rows - 1);
      float* out_min = &r.zmin.at(tx0, ty0 + ty);
      float* out_max = &r.zmax.at(tx0, ty0 + ty);
      if (level == kMinTileLevel) {
        reducePixelPairs(pixels + ya * stride, pixels + yb * stride, cols, out_min, out_max);
      } else {
        const TileDepthRange& below = tiles[level - 1];
        const int bx0 = x0 >> (level - 1), by0 = y0 >> (level - 1);
        reducePairs<true>(&below.zmin.at(bx0, by0 + ya), &below.zmin.at(bx0, by0 + yb), cols,
                          out_min);
        reducePairs<false>(&below.zmax.at(bx0, by0 + ya), &below.zmax.at(bx0, by0 + yb), cols,
                           out_max);
      }
    }
    cols = out_cols;
    rows = out_rows;
  }
}

void DepthBuffer::finishTileRanges() {
  for (int level = kBinTileLevel + 1; level <= kMaxTileLevel; ++level) {
    reduceRows(tiles[level - 1].zmin, tiles[level - 1].zmax, tiles[level], 0,
               tiles[level].zmin.height());
  }
}

const TileDepthRange& DepthBuffer::tileRange(int level) const {
  PENUMBRA_CHECK(level >= kMinTileLevel && level <= kMaxTileLevel,
                 "tile level {} is outside {}..{} (tiles of 2x2 to 256x256 pixels)", level,
                 kMinTileLevel, kMaxTileLevel);
  PENUMBRA_CHECK(tiles[level].level == level, "tile depth ranges were not built");
  return tiles[level];
}

}  // namespace penumbra
