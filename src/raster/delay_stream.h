#pragma once
// Delayed occlusion culling (Aila's 2005 thesis, section 5.1, after its publication P1): the
// eye pass's triangles pass through a ring buffer of a given byte size on their way to the
// pixels. When a triangle enters the ring its certain low-resolution depth information is
// entered into an occlusion buffer: per 8x8-pixel cell, the farthest depth the cell can still
// hold (the thesis' conservative z-max of unit A), raised only where entered triangles cover
// the whole cell: one triangle alone, or several whose pixels together fill it, each of their
// depths there counted at its farthest. When the triangle leaves the ring, the buffer already
// knows the triangles submitted after it that the ring held, and the triangle is tested
// against it and against the depth drawn so far in the cell (the early z-max test of unit B):
// where it lies strictly behind in every cell it reaches, it is culled before any pixel. Only
// strictly hidden triangles go, so every depth and primitive id of the frame is what the plain
// pass draws (ties keep the earlier triangle, as the depth kernel does).
//
// The rasterizer is sort-middle (binning.h): each bin tile draws its triangles in submission
// order, and the cells of a bin tile only ever learn from the triangles binned to it. So the
// stream is run per bin tile, with each triangle's position in the frame's stream deciding what
// the ring holds when it leaves, and gives the culling of one frame-wide ring exactly.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "raster/fixed_point.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// What one triangle takes in the ring: its three clip-space vertices (3 x 16 bytes) and its
// id. The thesis' rings hold shaded vertices with their attributes, so its megabytes hold
// fewer triangles than ours (docs/reproducing-visibility.md).
inline constexpr size_t kDelayStreamTriangleBytes = 3 * 16 + 4;
// The triangles a ring of `ring_bytes` holds: 0 for 0 (no stream), else at least 1.
size_t delayStreamTriangles(size_t ring_bytes);

// The occlusion buffer's cells: 8x8 pixels, the thesis' tile size (sections 4.3 and 5.1).
inline constexpr int kOcclusionCellLevel = 3;

inline constexpr CounterSpec kDelayRingTriangles{
    "delay_ring_triangles", "triangles the eye pass's delay stream holds (its ring size)"};
inline constexpr CounterSpec kDelayCulledPairs{
    "delay_culled_pairs",
    "of tiles_culled, the eye pass's (triangle, bin tile) pairs the delay stream culled"};
inline constexpr CounterSpec kEyeDepthPasses{
    "eye_depth_passes", "eye-pass pixels whose depth test passed (depth writes)"};
inline constexpr CounterSpec kEyeCoveredPixels{
    "eye_covered_pixels",
    "pixels a triangle covers in the eye pass (the optimum: one depth pass each)"};

// The stream as one bin tile sees it: the tile's triangles (indices into `setup`, increasing,
// [begin, end)) enter as the frame's stream reaches them and leave in the same order.
class DelayStreamTile {
 public:
  DelayStreamTile(const std::vector<SetupTriangle>& setup, const uint32_t* begin,
                  const uint32_t* end, const TileBox& box, size_t ring_triangles);
  // Called for the tile's triangle `*k` when it leaves the ring, with its edges `e` over the tile
  // and the tile's depth drawn so far (`depth`: kBinTileSize per row, the box's corner first):
  // enters every triangle the ring has taken in by then and answers whether the triangle is
  // strictly behind in every cell its rect reaches, so that it may be skipped.
  bool hidden(const uint32_t* k, const TileEdges& e, const float* depth);
  // After the triangle with edges `e` was drawn: the cells its rect reaches changed depth.
  void drawn(const TileEdges& e);

 private:
  static constexpr int kCellSize = 1 << kOcclusionCellLevel;
  static constexpr int kCellsPerRow = kBinTileSize / kCellSize;
  static constexpr int kCells = kCellsPerRow * kCellsPerRow;

  void enter(const SetupTriangle& t);
  // The pixels of cell (cx, cy) inside the triangle with edges `e` (bit 8 * row + column).
  uint64_t coverage(const TileEdges& e, int cx, int cy) const;
  // The bits of cell (cx, cy)'s pixels inside the image.
  uint64_t cellPixels(int cx, int cy) const;
  // The farthest depth drawn in cell i so far (background 0), recomputed when it changed.
  float drawnFarthest(int i, const float* depth);
  // The rect `e` restricted to cell (cx, cy) of the tile.
  TileEdges cellRect(const TileEdges& e, int cx, int cy) const;

  const std::vector<SetupTriangle>& setup_;
  const uint32_t* next_;  // the tile's next triangle to enter
  const uint32_t* end_;
  TileBox box_;
  size_t ring_;
  float occluded_[kCells] = {};  // no pixel of the cell will end farther (entered triangles)
  // Pixels of the cell that entered triangles cover, not filling it yet, and the farthest of
  // those triangles' depths there.
  uint64_t layer_[kCells] = {};
  float layer_farthest_[kCells];
  float drawn_farthest_[kCells] = {};
  bool changed_[kCells] = {};
};

}  // namespace penumbra
