#include "raster/delay_stream.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/cull_tiles.h"
#include "raster/plane_depth_range.h"

namespace penumbra {

size_t delayStreamTriangles(size_t ring_bytes) {
  if (ring_bytes == 0) return 0;
  return std::max<size_t>(1, ring_bytes / kDelayStreamTriangleBytes);
}

DelayStreamTile::DelayStreamTile(const std::vector<SetupTriangle>& setup, const uint32_t* begin,
                                 const uint32_t* end, const TileBox& box, size_t ring_triangles)
    : setup_(setup), next_(begin), end_(end), box_(box), ring_(std::max<size_t>(1, ring_triangles)) {}

TileEdges DelayStreamTile::cellRect(const TileEdges& e, int cx, int cy) const {
  TileEdges cell = e;
  const int x0 = box_.x0 + cx * kCellSize, y0 = box_.y0 + cy * kCellSize;
  cell.x0 = std::max(e.x0, x0);
  cell.y0 = std::max(e.y0, y0);
  cell.x1 = std::min(e.x1, x0 + kCellSize - 1);
  cell.y1 = std::min(e.y1, y0 + kCellSize - 1);
  return cell;
}

void DelayStreamTile::enter(const SetupTriangle& t) {
  TileEdges e;
  if (!setupTileRect(t, box_.x0, box_.y0, box_.x1, box_.y1, e)) return;
  // Only cells whose every pixel (within the image) lies in the triangle's box can be covered:
  // most triangles of a dense mesh span none, and are done before their edges are set up.
  auto first = [](int lo, int origin) { return (lo - origin + kCellSize - 1) >> kOcclusionCellLevel; };
  auto last = [](int hi, int origin, int box_hi) {
    return hi == box_hi ? (hi - origin) >> kOcclusionCellLevel
                        : ((hi - origin + 1) >> kOcclusionCellLevel) - 1;
  };
  const int cx0 = first(e.x0, box_.x0), cx1 = last(e.x1, box_.x0, box_.x1);
  const int cy0 = first(e.y0, box_.y0), cy1 = last(e.y1, box_.y0, box_.y1);
  if (cx0 > cx1 || cy0 > cy1) return;
  if (!setupRectEdges(t, e)) return;
  for (int cy = cy0; cy <= cy1; ++cy)
    for (int cx = cx0; cx <= cx1; ++cx) {
      const TileEdges cell = cellRect(e, cx, cy);
      // The kernels' own inside test at every pixel of the cell (cull_tiles.h); the box's
      // right and bottom edges are the image's where the tile is cut by it.
      if (!coversCell(cell, kOcclusionCellLevel, box_.x1 + 1, box_.y1 + 1)) continue;
      // Every depth the kernel draws in the cell is at least `lo`: each pixel of the cell ends
      // at least that close, whatever else is drawn there (reversed-Z: larger is closer).
      const double lo = planeDepthRange(t, cell).lo;
      float bound = float(lo);
      if (double(bound) > lo) bound = std::nextafter(bound, -std::numeric_limits<float>::infinity());
      float& occluded = occluded_[cy * kCellsPerRow + cx];
      occluded = std::max(occluded, bound);
    }
}

float DelayStreamTile::drawnFarthest(int i, const float* depth) {
  if (!changed_[i]) return drawn_farthest_[i];
  changed_[i] = false;
  const int x0 = (i % kCellsPerRow) * kCellSize, y0 = (i / kCellsPerRow) * kCellSize;
  const int x1 = std::min(x0 + kCellSize, box_.x1 - box_.x0 + 1);
  const int y1 = std::min(y0 + kCellSize, box_.y1 - box_.y0 + 1);
  float farthest = std::numeric_limits<float>::infinity();
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) farthest = std::min(farthest, depth[y * kBinTileSize + x]);
  drawn_farthest_[i] = farthest;
  return farthest;
}

bool DelayStreamTile::hidden(const uint32_t* k, const TileEdges& e, const float* depth) {
  // The ring holds the triangle and the ring_ - 1 submitted after it when it leaves (the last
  // ones leave when the frame's stream ends, after every triangle entered).
  const size_t position = *k;
  const size_t newest = ring_ - 1 >= setup_.size() - position ? setup_.size() - 1
                                                               : position + ring_ - 1;
  while (next_ != end_ && *next_ <= newest) enter(setup_[*next_++]);
  const SetupTriangle& t = setup_[position];
  // The plane over a cell's part of the box, or the vertices' range where that is nearer to
  // the truth (slivers, whose plane runs far past them across their box).
  const double vertex_nearest = vertexDepthRange(t).hi;
  const int cx0 = (e.x0 - box_.x0) >> kOcclusionCellLevel;
  const int cx1 = (e.x1 - box_.x0) >> kOcclusionCellLevel;
  const int cy0 = (e.y0 - box_.y0) >> kOcclusionCellLevel;
  const int cy1 = (e.y1 - box_.y0) >> kOcclusionCellLevel;
  for (int cy = cy0; cy <= cy1; ++cy)
    for (int cx = cx0; cx <= cx1; ++cx) {
      // Strictly behind: a triangle at the depth a pixel keeps could be the one that keeps it.
      const double nearest =
          std::min(planeDepthRange(t, cellRect(e, cx, cy)).hi, vertex_nearest);
      const int i = cy * kCellsPerRow + cx;
      if (nearest < double(occluded_[i])) continue;
      if (nearest < double(drawnFarthest(i, depth))) continue;
      return false;
    }
  return true;
}

void DelayStreamTile::drawn(const TileEdges& e) {
  for (int cy = (e.y0 - box_.y0) >> kOcclusionCellLevel;
       cy <= (e.y1 - box_.y0) >> kOcclusionCellLevel; ++cy)
    for (int cx = (e.x0 - box_.x0) >> kOcclusionCellLevel;
         cx <= (e.x1 - box_.x0) >> kOcclusionCellLevel; ++cx)
      changed_[cy * kCellsPerRow + cx] = true;
}

}  // namespace penumbra
