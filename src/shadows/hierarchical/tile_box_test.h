#pragma once
// Does a shadow-volume triangle cross a tile's 3D screen-space box (Aila's thesis, section 4.3,
// publication P2)? The box is the tile's pixel centres on screen times the depth range of the
// surfaces they show; the triangle is the one the kernels rasterize (snapped 28.4 edges) with
// its depth plane. Depth is affine in screen space (core/view.h), so over the convex set
// "triangle within the tile's rectangle" the plane takes every value between its extremes,
// found at that polygon's corners: the triangle misses the box exactly when that range lies
// wholly in front of or wholly behind the box. This is the separating-axis test of a triangle
// and a box, taken in the two screen axes (the clipping) and depth (the range), exact up to the
// margins below.
#include <cstdint>

#include "raster/triangle_setup.h"

namespace penumbra {

enum class TileBoxClass : uint8_t {
  Outside,   // no point of the triangle over the tile's pixel centres
  Front,     // over the tile, strictly in front of every surface depth of the box
  Behind,    // over the tile, strictly behind every surface depth of the box
  Crossing,  // may cross the box: the tile is a boundary tile of the triangle's volume
};

// Pixels [x0, x1] x [y0, y1] of the tile, inclusive; [zmin, zmax] the depths (reversed-Z) of
// the tile's surface pixels, zmin > 0.
//
// Conservative rounding: the rectangle is widened by one 28.4 unit, and the range by the float
// error of the kernels' depth evaluation (tile_kernels.h: TileEdges, evaluated from the bin
// tile's origin) plus the plane's change over 1/8 pixel. The latter covers two triangles of one
// volume that share an edge: their planes, fitted to unsnapped vertices, meet on the unsnapped
// edge, while coverage changes on the snapped one, up to 1/32 pixel away. So when one of them
// is Front (Behind) at a point of their edge over the tile, the other is Front (Behind) or
// Crossing there: a Front triangle never borders a Behind one inside a tile, which is what lets
// one sample decide the tile (tiled_volume_stencil.cpp).
TileBoxClass classifyTileBox(const SetupTriangle& t, int x0, int y0, int x1, int y1, float zmin,
                             float zmax);

// The same classes from the triangle's whole depth range (SetupTriangle::depth_min/max, over its
// vertices) instead of its part over a tile's pixels, with the same margin: Front or Behind
// hold wherever the triangle lies, Crossing may mean the triangle misses the box. Never
// Outside. A test of two comparisons where classifyTileBox clips.
TileBoxClass classifyDepthRange(const SetupTriangle& t, float zmin, float zmax);

// True when pixel (x, y)'s centre is inside the triangle, by the kernels' own test
// (triangle_setup.h: SetupTriangle, top-left rule included).
inline bool coversPixel(const SetupTriangle& t, int x, int y) {
  const int64_t px = int64_t(x) * 16 + 8, py = int64_t(y) * 16 + 8;
  for (int i = 0; i < 3; ++i)
    if (int64_t(t.A[i]) * px + int64_t(t.B[i]) * py + t.C[i] < 0) return false;
  return true;
}

}  // namespace penumbra
