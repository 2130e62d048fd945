#pragma once
// Binning of set-up triangles to bin tiles (fixed_point.h: kBinTileSize), so one worker owns a
// tile's pixels while it draws every triangle overlapping it, in input order.
#include <cstdint>
#include <vector>

#include "raster/triangle_setup.h"

namespace penumbra {

struct TileBins {
  int tiles_x = 0, tiles_y = 0;
  std::vector<uint32_t> offsets;  // tiles_x * tiles_y + 1 prefix sums into `triangles`
  std::vector<uint32_t> triangles;  // triangle indices, increasing within each tile

  size_t tileCount() const { return size_t(tiles_x) * size_t(tiles_y); }
};

TileBins binTriangles(const std::vector<SetupTriangle>& triangles, int width, int height);

}  // namespace penumbra
