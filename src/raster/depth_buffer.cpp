#include "raster/depth_buffer.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {

// Level 1 from the pixels, every further level from the one below (a min/max pyramid), each
// level's tiles covering only pixels inside the image.
void DepthBuffer::buildTileRanges() {
  const int w = depth.width(), h = depth.height();
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    TileDepthRange& r = tiles[level];
    r.level = level;
    const int size = 1 << level;
    const int tw = (w + size - 1) / size, th = (h + size - 1) / size;
    r.zmin.resize(tw, th);
    r.zmax.resize(tw, th);
    const TileDepthRange* below = level > kMinTileLevel ? &tiles[level - 1] : nullptr;
    parallelFor(size_t(th), [&](size_t row) {
      const int ty = int(row);
      for (int tx = 0; tx < tw; ++tx) {
        float lo = 2.0f, hi = -1.0f;
        if (below == nullptr) {
          for (int y = ty * 2; y < std::min(h, ty * 2 + 2); ++y)
            for (int x = tx * 2; x < std::min(w, tx * 2 + 2); ++x) {
              lo = std::min(lo, depth.at(x, y));
              hi = std::max(hi, depth.at(x, y));
            }
        } else {
          for (int y = ty * 2; y < std::min(below->zmin.height(), ty * 2 + 2); ++y)
            for (int x = tx * 2; x < std::min(below->zmin.width(), tx * 2 + 2); ++x) {
              lo = std::min(lo, below->zmin.at(x, y));
              hi = std::max(hi, below->zmax.at(x, y));
            }
        }
        r.zmin.at(tx, ty) = lo;
        r.zmax.at(tx, ty) = hi;
      }
    });
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
