// RowSpans (raster/tile_kernels.h): the row range and the per-row column spans the kernels
// visit. Both twins of every kernel skip what they exclude, so twin-against-twin tests cannot
// see a pixel both lose: here every covered pixel is found by brute force from the triangle's
// own edge functions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "raster/fixed_point.h"
#include "raster/tile_kernels.h"
#include "raster/triangle_setup.h"
#include "raster_test_util.h"

namespace penumbra {
namespace test_raster_row_spans {

using testing::TestRandom;

// Long thin triangles at every angle (shadow quads, wedge faces), fat ones, and tiny ones.
ClipTriangles mixedTriangles(int count, int width, int height, uint64_t seed) {
  TestRandom random(seed);
  ClipTriangles tris;
  for (int t = 0; t < count; ++t) {
    const double x = random.uniform(-60, width + 60), y = random.uniform(-60, height + 60);
    const double angle = random.uniform(0, 6.2832);
    const double length = t % 3 == 2 ? random.uniform(0.5, 6) : random.uniform(5, 700);
    const double thickness = t % 3 == 0 ? random.uniform(0.2, 4) : random.uniform(1, 120);
    const double dx = std::cos(angle), dy = std::sin(angle);
    const double skew = random.uniform(-1, 1);
    tris.clip.push_back(testing::screenToClip(x, y, 0.5, width, height));
    tris.clip.push_back(testing::screenToClip(x + dx * length, y + dy * length, 0.5, width, height));
    tris.clip.push_back(testing::screenToClip(x + dx * length * skew - dy * thickness,
                                              y + dy * length * skew + dx * thickness, 0.5, width,
                                              height));
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  return tris;
}

bool covered(const SetupTriangle& t, int x, int y) {
  for (int i = 0; i < 3; ++i)
    if (int64_t(t.A[i]) * pixelCentre(x) + int64_t(t.B[i]) * pixelCentre(y) + t.C[i] < 0)
      return false;
  return true;
}

constexpr int kWidth = 250, kHeight = 170;

// Calls fn(t, e) for every triangle of the mix (seeded by `seed`) and every bin tile its edges
// reach, e set up for the tile as the kernels get it.
template <class Fn>
void forEachRect(uint64_t seed, Fn&& fn) {
  const std::vector<SetupTriangle> setup =
      setupTriangles(mixedTriangles(1500, kWidth, kHeight, seed), kWidth, kHeight);
  for (const SetupTriangle& t : setup)
    for (int ty = 0; ty * kBinTileSize < kHeight; ++ty)
      for (int tx = 0; tx * kBinTileSize < kWidth; ++tx) {
        const int x0 = tx * kBinTileSize, y0 = ty * kBinTileSize;
        TileEdges e;
        if (setupTileEdges(t, x0, y0, std::min(kWidth, x0 + kBinTileSize) - 1,
                           std::min(kHeight, y0 + kBinTileSize) - 1, e))
          fn(t, e);
      }
}

TEST(RasterRowSpans, RowsAndSpansHoldEveryCoveredPixel) {
  uint64_t rect_rows = 0, kept_rows = 0, pixels = 0;
  forEachRect(17, [&](const SetupTriangle& t, const TileEdges& e) {
    const RowSpans spans(e);
    int y_lo = 0, y_hi = -1;
    const bool any_row = spans.rows(y_lo, y_hi);
    if (any_row) {
      ASSERT_GE(y_lo, e.y0);
      ASSERT_LE(y_hi, e.y1);
      kept_rows += uint64_t(y_hi - y_lo + 1);
    }
    rect_rows += uint64_t(e.y1 - e.y0 + 1);
    for (int y = e.y0; y <= e.y1; ++y) {
      const int ry = y - e.ty0;
      const int32_t r[3] = {e.e0[0] + e.dy[0] * ry, e.e0[1] + e.dy[1] * ry,
                            e.e0[2] + e.dy[2] * ry};
      int x_lo = 0, x_hi = -1;
      const bool any_column = spans.span(r, x_lo, x_hi);
      for (int x = e.x0; x <= e.x1; ++x) {
        if (!covered(t, x, y)) continue;
        ++pixels;
        // If these fail, the kernels skip a covered pixel: a hole in the image, a stencil
        // count lost (a light leak or a false shadow).
        ASSERT_TRUE(any_row && y >= y_lo && y <= y_hi) << "row " << y << " outside the rows";
        ASSERT_TRUE(any_column && x >= x_lo && x <= x_hi) << "pixel " << x << "," << y;
      }
    }
  });
  EXPECT_GT(pixels, 100000u);
  // The row range is what it is for: most of the rect rows of long slanted triangles are empty.
  EXPECT_LT(double(kept_rows), 0.8 * double(rect_rows));
  std::printf("[ rows     ] %llu of %llu rect rows kept, %llu covered pixels\n",
              (unsigned long long)kept_rows, (unsigned long long)rect_rows,
              (unsigned long long)pixels);
}

// The SIMD kernels take their rows' spans a batch at a time (rowSpans: several rows per SIMD
// step in double). If the batch differed from span(), which the test above holds to every
// covered pixel, a SIMD kernel could skip a covered pixel that the scalar twin draws (a hole,
// or a stencil count lost) or visit columns its twin does not; both twins are compared here
// row by row, on the same mix of slivers, fat and tiny triangles, for batches starting at
// every third row of each rect and running to its end (or one row short), up to kRowSpanBatch.
TEST(RasterRowSpans, BatchedSpansAreTheRowByRowSpans) {
  uint64_t rows = 0, empty = 0;
  forEachRect(23, [&](const SetupTriangle&, const TileEdges& e) {
    // A kernel starts at its row range's first row and takes up to kRowSpanBatch rows.
    const int rect_rows = e.y1 - e.y0 + 1;
    for (int first = e.y0; first <= e.y1; first += 3) {
      const int count = std::min(kRowSpanBatch, e.y1 - first + 1 - (first - e.y0) % 2);
      if (count < 1) continue;
      int32_t simd_lo[kRowSpanArray], simd_hi[kRowSpanArray];
      int32_t scalar_lo[kRowSpanArray], scalar_hi[kRowSpanArray];
      rowSpans(e, first, count, simd_lo, simd_hi, true);
      rowSpansScalar(e, first, count, scalar_lo, scalar_hi);
      for (int k = 0; k < count; ++k) {
        ASSERT_EQ(simd_lo[k], scalar_lo[k]) << "row " << first + k << " of " << rect_rows;
        ASSERT_EQ(simd_hi[k], scalar_hi[k]) << "row " << first + k << " of " << rect_rows;
        ++rows;
        empty += scalar_lo[k] > scalar_hi[k];
      }
    }
  });
  // Both outcomes occur: rows with a span and rows the slivers leave empty.
  EXPECT_GT(rows, 100000u);
  EXPECT_GT(empty, rows / 20);
  EXPECT_LT(empty, rows - rows / 20);
}

}  // namespace test_raster_row_spans
}  // namespace penumbra
