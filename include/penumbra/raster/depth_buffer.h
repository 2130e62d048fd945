#pragma once
// The eye pass's output: depth per pixel and, per tile of 2^n x 2^n pixels (n = 1..8), the
// minimum and maximum depth of the tile (the z-min/z-max of the 2004 paper, section 4).
//
// Depth is reversed-Z (core/view.h): 1 at the near plane, smaller is farther, 0 is infinity
// and marks pixels no triangle covered (background). Tile z-min/z-max cover only the pixels
// inside the image; a tile of only background pixels has z-min = z-max = 0.
#include <array>
#include <cstdint>
#include <vector>

#include <penumbra/core/image.h>
#include <penumbra/core/math.h>

namespace penumbra {

inline constexpr int kMinTileLevel = 1;  // 2x2 tiles
inline constexpr int kMaxTileLevel = 8;  // 256x256 tiles

struct TileDepthRange {
  int level = 0;  // tile size is 1 << level pixels
  Image<float> zmin;  // one entry per tile, tiles in row-major order
  Image<float> zmax;
};

struct DepthBuffer {
  Image<float> depth;
  std::array<TileDepthRange, kMaxTileLevel + 1> tiles;  // indexed by level; [0] unused

  int width() const { return depth.width(); }
  int height() const { return depth.height(); }
  // Rebuilds tiles[kMinTileLevel..kMaxTileLevel] from `depth`.
  void buildTileRanges();
  // The same ranges built by a pass that writes `depth` in 32x32 bin tiles
  // (raster/rasterizer.cpp), each tile's levels 1..5 taken from its pixels while they are still
  // in cache instead of reading the whole buffer again: allocateTileRanges sizes the levels,
  // setBinTileRanges fills levels 1..5 over one bin tile's pixels [x0, x1] x [y0, y1] (x0, y0
  // multiples of 32) from `pixels` (row-major, `stride` per row, pixel (x0, y0) first; threads
  // may fill different bin tiles at once), finishTileRanges builds levels 6..8 from level 5.
  // Min and max are exact, so the result equals buildTileRanges' bit for bit.
  void allocateTileRanges();
  void setBinTileRanges(const float* pixels, int stride, int x0, int y0, int x1, int y1);
  void finishTileRanges();
  const TileDepthRange& tileRange(int level) const;
};

// Per-pixel surface identity for shading and for techniques that need the visible surface's
// orientation (the oracle offsets its rays off the surface toward the eye).
inline constexpr uint32_t kNoPrimitive = 0xffffffffu;

struct EyeBuffers {
  DepthBuffer depth;
  // Global triangle id: triangles are numbered mesh after mesh in Scene::meshes order;
  // kNoPrimitive where the background shows.
  Image<uint32_t> primitive;
  // The frame's clip-space vertices: View::toClip of every mesh's positions, mesh after mesh,
  // computed once by the eye pass. Shadow volumes and wedges take their finite vertices from
  // here, so a light cap is bit-identical to the surface it comes from by construction.
  std::vector<vec4> clip_vertices;
  std::vector<uint32_t> mesh_vertex_base;  // per mesh, the index of its vertex 0 above
};

}  // namespace penumbra
