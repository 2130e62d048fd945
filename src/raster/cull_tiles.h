#pragma once
// Tiles for z-min/z-max occlusion culling (2004 paper, section 4), of any size 2^n, n = 1..8,
// walked inside the bin tiles that own the pixels (fixed_point.h: kBinTileSize).
#include <algorithm>

#include "raster/depth_buffer.h"
#include "raster/fixed_point.h"
#include "raster/tile_kernels.h"

namespace penumbra {

// Calls fn(sub, zmin, zmax) for every culling tile of `range` that the triangle rect of `e`
// touches, with `sub` restricted to that culling tile's pixels. Culling tiles smaller than a bin
// tile split the rect; a culling tile at least as large as the bin tile contains it whole.
template <class Fn>
void forEachCullTile(const TileEdges& e, const TileDepthRange& range, Fn&& fn) {
  const int level = range.level;
  if (level >= kBinTileLevel) {
    fn(e, range.zmin.at(e.x0 >> level, e.y0 >> level), range.zmax.at(e.x0 >> level, e.y0 >> level));
    return;
  }
  const int size = 1 << level;
  for (int cy = e.y0 >> level; cy <= (e.y1 >> level); ++cy) {
    for (int cx = e.x0 >> level; cx <= (e.x1 >> level); ++cx) {
      TileEdges sub = e;
      sub.x0 = std::max(e.x0, cx * size);
      sub.y0 = std::max(e.y0, cy * size);
      sub.x1 = std::min(e.x1, cx * size + size - 1);
      sub.y1 = std::min(e.y1, cy * size + size - 1);
      fn(sub, range.zmin.at(cx, cy), range.zmax.at(cx, cy));
    }
  }
}

// True when no pixel of the rect can pass the triangle's depth rule against a tile whose stored
// depths lie in [zmin, zmax] (reversed-Z): z-pass needs the triangle in front of some pixel (so
// only the tile's farthest depth, the papers' z-max, matters), z-fail behind or at some pixel
// (the tile's nearest, z-min). The triangle's depth over the rect is bounded by its plane at the
// rect's corners, widened by the float error of the kernels' evaluation, so culling never
// changes a pixel. Tiles of only background are culled: there is nothing to shadow.
bool depthRuleCulled(const SetupTriangle& t, const TileEdges& e, bool zfail, float zmin, float zmax);

}  // namespace penumbra
