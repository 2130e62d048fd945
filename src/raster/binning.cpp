#include "raster/binning.h"

#include "raster/fixed_point.h"

namespace penumbra {

// Two sequential passes (count, then fill) over the triangles' tile boxes: it is linear in the
// number of (triangle, tile) pairs and keeps each tile's list in triangle order, which makes
// depth ties resolve the same way for any thread count.
TileBins binTriangles(const std::vector<SetupTriangle>& triangles, int width, int height) {
  TileBins bins;
  bins.tiles_x = (width + kBinTileSize - 1) / kBinTileSize;
  bins.tiles_y = (height + kBinTileSize - 1) / kBinTileSize;
  bins.offsets.assign(bins.tileCount() + 1, 0);
  for (const SetupTriangle& t : triangles) {
    for (int ty = t.min_y >> kBinTileLevel; ty <= (t.max_y >> kBinTileLevel); ++ty)
      for (int tx = t.min_x >> kBinTileLevel; tx <= (t.max_x >> kBinTileLevel); ++tx)
        ++bins.offsets[size_t(ty) * bins.tiles_x + tx + 1];
  }
  for (size_t i = 1; i < bins.offsets.size(); ++i) bins.offsets[i] += bins.offsets[i - 1];
  bins.triangles.resize(bins.offsets.back());
  std::vector<uint32_t> cursor(bins.offsets.begin(), bins.offsets.end() - 1);
  for (uint32_t i = 0; i < triangles.size(); ++i) {
    const SetupTriangle& t = triangles[i];
    for (int ty = t.min_y >> kBinTileLevel; ty <= (t.max_y >> kBinTileLevel); ++ty)
      for (int tx = t.min_x >> kBinTileLevel; tx <= (t.max_x >> kBinTileLevel); ++tx)
        bins.triangles[cursor[size_t(ty) * bins.tiles_x + tx]++] = i;
  }
  return bins;
}

}  // namespace penumbra
