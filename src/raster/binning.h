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

// A bin's triangles are read in index order but lie anywhere in the set-up array, and a dense
// mesh's records do not stay in cache from one tile to the next: a pass over a bin asks for the
// record kBinLookahead triangles ahead, both of its cache lines.
inline constexpr uint32_t kBinLookahead = 4;
inline void prefetchSetupTriangle(const SetupTriangle& t) {
  const char* p = reinterpret_cast<const char*>(&t);
  __builtin_prefetch(p);
  __builtin_prefetch(p + sizeof(SetupTriangle) - 1);
}

}  // namespace penumbra
