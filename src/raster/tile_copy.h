#pragma once
// A bin tile's pixels of an image in a contiguous copy, for the passes that draw a tile's
// triangles one after another: the copy stays in L1 while they read and write it. In place, a
// tile's 32 rows lie one image row apart, which at 1920 (or 640) pixels is a multiple of 512
// bytes: the rows of two such buffers fall into a sixteenth of the L1 cache sets, and the first
// load of each row stalls the eye pass's depth kernel for most of its time (bench/README.md).
#include <algorithm>
#include <cstdint>

#include "core/image.h"
#include "raster/fixed_point.h"

namespace penumbra {

// Pixels [x0, x1] x [y0, y1] of one bin tile, inclusive.
struct TileBox {
  int x0, y0, x1, y1;
};

// Asks for the cache lines of `count` elements from `first` (a bin tile's row of a frame-sized
// image), for reading or for writing: a tile's rows lie one image row apart, which no hardware
// prefetcher follows, so a pass that reads or writes them after drawing the tile asks first.
template <class T>
void prefetchRow(const T* first, int count, bool write) {
  // Every line from the first element's to the last one's (a row need not start on a line).
  const uintptr_t last = reinterpret_cast<uintptr_t>(first + count) - 1;
  for (uintptr_t line = reinterpret_cast<uintptr_t>(first) & ~uintptr_t(63); line <= last;
       line += 64) {
    if (write)
      __builtin_prefetch(reinterpret_cast<const void*>(line), 1);
    else
      __builtin_prefetch(reinterpret_cast<const void*>(line), 0);
  }
}

// prefetchRow for every row of `box` in `image`: a pass that reads or writes a bin tile's rows
// of a frame-sized image after drawing the tile asks for them when the tile starts.
template <class T>
void prefetchTileRows(const Image<T>& image, const TileBox& box, bool write) {
  for (int y = box.y0; y <= box.y1; ++y)
    prefetchRow(&image.at(box.x0, y), box.x1 - box.x0 + 1, write);
}

template <class T>
class TileCopy {
 public:
  // A copy of the tile's pixels of `image`.
  TileCopy(const Image<T>& image, const TileBox& box) {
    for (int y = box.y0; y <= box.y1; ++y)
      std::copy_n(&image.at(box.x0, y), box.x1 - box.x0 + 1,
                  pixels_ + (y - box.y0) * kBinTileSize);
  }
  // Uninitialised, for a pass that sets every pixel it stores before storeTo.
  TileCopy() = default;
  // Every pixel `fill`, for a pass that writes the whole tile.
  explicit TileCopy(T fill) { std::fill_n(pixels_, kBinTileSize * kBinTileSize, fill); }

  // Row-major, kBinTileSize pixels per row; pixel (x, y) of the image is element
  // (y - box.y0) * kBinTileSize + (x - box.x0).
  T* data() { return pixels_; }
  void storeTo(Image<T>& image, const TileBox& box) const {
    for (int y = box.y0; y <= box.y1; ++y)
      std::copy_n(pixels_ + (y - box.y0) * kBinTileSize, box.x1 - box.x0 + 1,
                  &image.at(box.x0, y));
  }

 private:
  alignas(64) T pixels_[kBinTileSize * kBinTileSize];
};

}  // namespace penumbra
