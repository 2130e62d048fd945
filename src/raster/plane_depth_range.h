#pragma once
// Bounds of a triangle's depth over a rect of pixels, safe for decisions that must never
// change a pixel: tile culling (rasterizer.cpp: depthRuleTiles) and delayed occlusion culling
// (delay_stream.cpp).
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "raster/fixed_point.h"
#include "raster/tile_kernels.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// The plane's extremes over the rect's pixel centres, widened by the float error of the kernels'
// evaluation (tile_kernels.h: TileEdges), so every depth a kernel computes for a pixel of the
// rect lies in [lo, hi].
struct PlaneDepthRange {
  double lo, hi;
};

inline PlaneDepthRange planeDepthRange(const SetupTriangle& t, const TileEdges& e) {
  // At the first corner plus each step across the rect taken where it lowers (raises) the depth.
  const double c00 = t.a * (e.x0 + 0.5) + t.b * (e.y0 + 0.5) + t.c;
  const double across = t.a * (e.x1 - e.x0), down = t.b * (e.y1 - e.y0);
  const double error = 8.0 * FLT_EPSILON *
                       (std::fabs(e.dc) + kBinTileSize * (std::fabs(e.da) + std::fabs(e.db))) +
                       1e-30;
  return {c00 + std::min(across, 0.0) + std::min(down, 0.0) - error,
          c00 + std::max(across, 0.0) + std::max(down, 0.0) + error};
}

// The depths the kernels can give the triangle's pixels, from its vertices' range
// (SetupTriangle::depth_min/max) instead of its plane over a rect: much tighter than the plane's
// extremes over a rect for a sliver whose plane is steep across its box. The margin is the
// float error of the kernels' evaluation from a bin tile's origin (within four bin tiles of
// reach) plus the plane's change over 1/8 pixel: coverage is decided on vertices snapped up to
// 1/32 pixel away from the unsnapped ones the plane and the range come from.
inline PlaneDepthRange vertexDepthRange(const SetupTriangle& t) {
  const double reach = std::fabs(t.a) + std::fabs(t.b);
  const double lo = t.depth_min, hi = t.depth_max;
  const double error =
      8.0 * FLT_EPSILON * (std::max(std::fabs(lo), std::fabs(hi)) + 4.0 * kBinTileSize * reach) +
      reach / 8.0 + 1e-30;
  return {lo - error, hi + error};
}

}  // namespace penumbra
