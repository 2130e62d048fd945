#pragma once
// The coarse level of a two-level stencil (the storage Aila's 2005 thesis proposes in section
// 4.3, publication P2): one value per culling tile of a bin tile, for the contributions of
// shadow-volume polygons that cover a whole culling tile and pass the depth test at every one
// of its pixels (the z-min trivial accept of the thesis's section 1.5, not section 4.3's
// per-volume tile classification, which is shadows/hierarchical/). Such a
// polygon adds the same value to every pixel of the tile, so it adds it once, here, instead of
// reading each pixel's depth and writing its stencil; the cells are added to the pixels once,
// when the bin tile's copy is stored. Integer addition (wrapping, for the LI buffer) does not
// depend on order, so the buffer ends bit for bit as the per-pixel passes leave it.
//
// Counted as memory accesses: one coarse write per (polygon, culling tile), and one pixel write
// per pixel of a cell whose sum is not zero when the cells are applied. A shadow volume that
// passes in front of a whole tile adds +1 and -1 there and costs two coarse writes and no pixel
// write.
#include <algorithm>
#include <cstdint>

#include "raster/fixed_point.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"

namespace penumbra {

class TileOffsets {
 public:
  // Cells of culling tiles of 2^level pixels (one cell per bin tile from kBinTileLevel up).
  explicit TileOffsets(int level)
      : level_(std::min(level, kBinTileLevel)), per_row_(kBinTileSize >> level_) {
    std::fill_n(cells_, per_row_ * per_row_, 0);
  }

  // Adds `value` to the cells of `rect`, a rectangle of whole cells of one bin tile (the rect a
  // forEachCullRect draw receives for a code with a whole bit).
  void add(const TileEdges& rect, int32_t value) {
    const int cx0 = (rect.x0 - rect.tx0) >> level_, cx1 = (rect.x1 - rect.tx0) >> level_;
    const int cy0 = (rect.y0 - rect.ty0) >> level_, cy1 = (rect.y1 - rect.ty0) >> level_;
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) cells_[cy * per_row_ + cx] += value;
    cells_written_ += uint64_t(cx1 - cx0 + 1) * uint64_t(cy1 - cy0 + 1);
  }

  bool used() const { return cells_written_ > 0; }

  // Adds each cell's sum to its pixels of the bin tile `box`, held in a TileCopy's layout
  // (kBinTileSize pixels per row): add(pixel, sum) for every pixel of a cell whose sum is not
  // zero. Counts the (polygon, culling tile) pairs taken whole into `accepted` and every coarse
  // and pixel write into `writes`.
  template <class T, class Add>
  void applyTo(T* pixels, const TileBox& box, Add&& add, uint64_t& writes,
               uint64_t& accepted) const {
    if (!used()) return;
    accepted += cells_written_;
    writes += cells_written_;
    const int size = 1 << level_;
    const int w = box.x1 - box.x0 + 1, h = box.y1 - box.y0 + 1;
    for (int cy = 0; cy < per_row_ && cy * size < h; ++cy)
      for (int cx = 0; cx < per_row_ && cx * size < w; ++cx) {
        const int32_t sum = cells_[cy * per_row_ + cx];
        if (sum == 0) continue;
        const int x1 = std::min(w, (cx + 1) * size), y1 = std::min(h, (cy + 1) * size);
        for (int y = cy * size; y < y1; ++y)
          for (int x = cx * size; x < x1; ++x) add(pixels[y * kBinTileSize + x], sum);
        writes += uint64_t(x1 - cx * size) * uint64_t(y1 - cy * size);
      }
  }

 private:
  int level_, per_row_;
  uint64_t cells_written_ = 0;
  int32_t cells_[(kBinTileSize / 2) * (kBinTileSize / 2)];
};

}  // namespace penumbra
