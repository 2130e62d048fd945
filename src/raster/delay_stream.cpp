#include "raster/delay_stream.h"

#include <algorithm>
#include <cmath>
#include <iterator>
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
    : setup_(setup),
      next_(begin),
      end_(end),
      box_(box),
      ring_(std::max<size_t>(1, ring_triangles)) {
  std::fill(std::begin(layer_farthest_), std::end(layer_farthest_),
            std::numeric_limits<float>::infinity());
}

TileEdges DelayStreamTile::cellRect(const TileEdges& e, int cx, int cy) const {
  TileEdges cell = e;
  const int x0 = box_.x0 + cx * kCellSize, y0 = box_.y0 + cy * kCellSize;
  cell.x0 = std::max(e.x0, x0);
  cell.y0 = std::max(e.y0, y0);
  cell.x1 = std::min(e.x1, x0 + kCellSize - 1);
  cell.y1 = std::min(e.y1, y0 + kCellSize - 1);
  return cell;
}

uint64_t DelayStreamTile::coverage(const TileEdges& e, int cx, int cy) const {
  const TileEdges cell = cellRect(e, cx, cy);
  const int x0 = box_.x0 + cx * kCellSize, y0 = box_.y0 + cy * kCellSize;
  uint64_t mask = 0;
  for (int y = cell.y0; y <= cell.y1; ++y) {
    const int ry = y - e.ty0;
    for (int x = cell.x0; x <= cell.x1; ++x) {
      const int rx = x - e.tx0;
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside &= e.e0[i] + e.dx[i] * rx + e.dy[i] * ry >= 0;
      if (inside) mask |= uint64_t(1) << ((y - y0) * kCellSize + (x - x0));
    }
  }
  return mask;
}

uint64_t DelayStreamTile::cellPixels(int cx, int cy) const {
  const int w = std::min(kCellSize, box_.x1 - (box_.x0 + cx * kCellSize) + 1);
  const int h = std::min(kCellSize, box_.y1 - (box_.y0 + cy * kCellSize) + 1);
  const uint64_t row = (uint64_t(1) << w) - 1;
  uint64_t mask = 0;
  for (int y = 0; y < h; ++y) mask |= row << (y * kCellSize);
  return mask;
}

void DelayStreamTile::enter(const SetupTriangle& t) {
  TileEdges e;
  if (!setupTileEdges(t, box_.x0, box_.y0, box_.x1, box_.y1, e)) return;
  const double vertex_farthest = vertexDepthRange(t).lo;
  for (int cy = (e.y0 - box_.y0) >> kOcclusionCellLevel;
       cy <= (e.y1 - box_.y0) >> kOcclusionCellLevel; ++cy)
    for (int cx = (e.x0 - box_.x0) >> kOcclusionCellLevel;
         cx <= (e.x1 - box_.x0) >> kOcclusionCellLevel; ++cx) {
      // Every depth the kernel draws at the triangle's pixels of the cell is at least
      // `farthest`: those pixels end at least that close, whatever else is drawn there
      // (reversed-Z: larger is closer).
      const double lo =
          std::max(planeDepthRange(t, cellRect(e, cx, cy)).lo, vertex_farthest);
      float farthest = float(lo);
      if (double(farthest) > lo)
        farthest = std::nextafter(farthest, -std::numeric_limits<float>::infinity());
      const int i = cy * kCellsPerRow + cx;
      if (farthest <= occluded_[i]) continue;  // it cannot raise the bound
      // The kernels' own inside test (their int32 edge values) at each pixel of the cell.
      const uint64_t covered = coverage(e, cx, cy);
      if (covered == 0) continue;
      const uint64_t full = cellPixels(cx, cy);
      if ((covered & full) == full) {
        occluded_[i] = farthest;
        if (layer_farthest_[i] <= farthest) {
          layer_[i] = 0;
          layer_farthest_[i] = std::numeric_limits<float>::infinity();
        }
        continue;
      }
      // Triangles that each cover part of the cell add up: once their pixels fill it, it ends
      // at least as close as the farthest of them (one coverage layer per cell, in the manner
      // of masked depth culling; the thesis' unit A takes whole covers only). The layer is
      // kept useful: a triangle much nearer than the layer starts a new one, a triangle much
      // farther, which would drag the layer down towards the bound, is left out. Which
      // triangles join only decides how much is culled, never a pixel.
      float& layer_far = layer_farthest_[i];
      const float bound = occluded_[i];
      if (layer_[i] == 0) {
        layer_[i] = covered;
        layer_far = farthest;
      } else if (farthest >= layer_far) {
        if (layer_far - bound < farthest - layer_far) {
          layer_[i] = covered;
          layer_far = farthest;
        } else {
          layer_[i] |= covered;
        }
      } else if (farthest - bound >= layer_far - farthest) {
        layer_[i] |= covered;
        layer_far = farthest;
      }
      if ((layer_[i] & full) == full) {
        occluded_[i] = std::max(occluded_[i], layer_far);
        layer_[i] = 0;
        layer_farthest_[i] = std::numeric_limits<float>::infinity();
      }
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
