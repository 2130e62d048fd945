#include "raster/binning.h"

#include <algorithm>

#include "core/parallel.h"
#include "raster/fixed_point.h"

namespace penumbra {
namespace {

// The bin tiles of row `ty` that the triangle's pixel box meets and no edge excludes: exactly
// the tiles where setupRectEdges finds every edge non-negative somewhere in the box's part of
// the tile (its corner test), so every pair handed out is one the passes draw or cull, never
// one they skip (the tile counters count culling tests, not binning slack). Shadow volume quads
// and wedge faces are long and slanted: their bounding boxes hold ten times more tiles than
// they touch (columns, 1920x1080: 1.74M box pairs, 0.16M touched).
//
// Per edge, k is its largest value over the row band without the x term; over a tile's part of
// the box the edge is largest at the part's last column when A > 0 and at its first when
// A < 0, so the tiles where it can be >= 0 are a half-line of tiles, found exactly in
// integers: A > 0, from the tile holding the first pixel x with A (16 x + 8) + k >= 0; A < 0,
// up to the tile holding the last such pixel. The row's set is their intersection, one
// interval. (Until 2026-12-07 the interval was estimated in double and its ends trimmed tile by
// tile with the corner test: the same tiles, at 1.6-3.4 times the cost.)
bool tileRowSpan(const SetupTriangle& t, int ty, int& cx0, int& cx1) {
  const int ya = std::max(t.min_y, ty * kBinTileSize);
  const int yb = std::min(t.max_y, ty * kBinTileSize + kBinTileSize - 1);
  int64_t k[3];
  int64_t lo = t.min_x >> kBinTileLevel, hi = t.max_x >> kBinTileLevel;
  // A box within one column of tiles (most of a dense mesh's triangles): the corner test of
  // that tile alone decides, cheaper than the divisions.
  const bool one_column = lo == hi;
  for (int i = 0; i < 3; ++i) {
    const int64_t A = t.A[i], B = t.B[i];
    k[i] = std::max(B * pixelCentre(ya), B * pixelCentre(yb)) + t.C[i];
    if (A == 0) {
      if (k[i] < 0) return false;
      continue;
    }
    if (one_column) continue;
    if (A > 0) {
      const int64_t first = firstPixelFrom(ceilDiv(-k[i], A));
      if (first > t.max_x) return false;
      lo = std::max(lo, floorDiv(first, kBinTileSize));
    } else {
      const int64_t last = lastPixelTo(floorDiv(k[i], -A));
      if (last < t.min_x) return false;
      hi = std::min(hi, floorDiv(last, kBinTileSize));
    }
  }
  if (one_column) {
    for (int i = 0; i < 3; ++i) {
      const int64_t A = t.A[i];
      if (std::max(A * pixelCentre(t.min_x), A * pixelCentre(t.max_x)) + k[i] < 0) return false;
    }
  }
  cx0 = int(lo);
  cx1 = int(hi);
  return cx0 <= cx1;
}

}  // namespace

// Each triangle's tile-row spans are solved once, in parallel (they are most of the work),
// then two passes (count, then fill) over them, each in parallel over runs of triangles: linear
// in the number of (triangle, tile) pairs, and each tile's list stays in triangle order, which
// makes depth ties resolve the same way for any thread count.
TileBins binTriangles(const std::vector<SetupTriangle>& triangles, int width, int height) {
  TileBins bins;
  bins.tiles_x = (width + kBinTileSize - 1) / kBinTileSize;
  bins.tiles_y = (height + kBinTileSize - 1) / kBinTileSize;
  bins.offsets.assign(bins.tileCount() + 1, 0);
  // Spans of triangle i: tile rows first_row[i] .. + (span_begin[i + 1] - span_begin[i]) - 1.
  const size_t n = triangles.size();
  std::vector<uint32_t> span_begin(n + 1, 0);
  for (size_t i = 0; i < n; ++i)
    span_begin[i + 1] = span_begin[i] + uint32_t((triangles[i].max_y >> kBinTileLevel) -
                                                 (triangles[i].min_y >> kBinTileLevel) + 1);
  struct Span {
    int32_t first, last;  // tile columns, first > last: none
  };
  std::vector<Span> spans(span_begin.back());
  constexpr size_t kChunk = 256;
  parallelFor((n + kChunk - 1) / kChunk, [&](size_t c) {
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
      const SetupTriangle& t = triangles[i];
      Span* out = &spans[span_begin[i]];
      for (int ty = t.min_y >> kBinTileLevel; ty <= (t.max_y >> kBinTileLevel); ++ty, ++out)
        if (!tileRowSpan(t, ty, out->first, out->last)) *out = {1, 0};
    }
  });
  auto forEachTileOf = [&](size_t i, auto&& fn) {
    int ty = triangles[i].min_y >> kBinTileLevel;
    for (uint32_t k = span_begin[i]; k < span_begin[i + 1]; ++k, ++ty)
      for (int tx = spans[k].first; tx <= spans[k].last; ++tx) fn(size_t(ty) * bins.tiles_x + tx);
  };
  // Count, then fill, in parallel over runs of triangles: run r's pairs with a tile go after
  // those of the runs before it, so each tile's list is in triangle order whatever the runs.
  // Runs of at least 4096 triangles, at most 64, and at most 4M (run, tile) counters.
  const size_t tiles = bins.tileCount();
  const size_t runs = std::min(std::clamp<size_t>(n / 4096, 1, 64),
                               std::max<size_t>(1, (size_t(1) << 22) / tiles));
  const size_t per_run = (n + runs - 1) / runs;
  // Run r's count of tile t's pairs at [r * tiles + t], then the count of the runs before it.
  std::vector<uint32_t> counts(runs * tiles, 0);
  parallelFor(runs, [&](size_t r) {
    uint32_t* count = &counts[r * tiles];
    for (size_t i = r * per_run; i < std::min(n, (r + 1) * per_run); ++i)
      forEachTileOf(i, [&](size_t tile) { ++count[tile]; });
  });
  for (size_t t = 0; t < tiles; ++t) {
    uint32_t sum = 0;  // the pairs of tile t in the runs before r
    for (size_t r = 0; r < runs; ++r) {
      const uint32_t count = counts[r * tiles + t];
      counts[r * tiles + t] = sum;
      sum += count;
    }
    bins.offsets[t + 1] = bins.offsets[t] + sum;
  }
  bins.triangles.resize(bins.offsets.back());
  parallelFor(runs, [&](size_t r) {
    uint32_t* cursor = &counts[r * tiles];
    for (size_t i = r * per_run; i < std::min(n, (r + 1) * per_run); ++i)
      forEachTileOf(i, [&](size_t tile) {
        bins.triangles[bins.offsets[tile] + cursor[tile]++] = uint32_t(i);
      });
  });
  return bins;
}

}  // namespace penumbra
