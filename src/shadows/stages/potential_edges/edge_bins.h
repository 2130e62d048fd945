#pragma once
// Where on screen the potential silhouette edges (and the triangles cutting the light) can
// matter: per-tile lists, and per edge the planes of the per-pixel quick reject.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "shadows/stages/potential_edges/edge_screen_test.h"
#include "shadows/stages/potential_edges/potential_edges.h"

namespace penumbra {

// Screen tiles of 2^level pixels and, per tile, the potential edges whose region of influence
// (the points from which the edge's projection can overlap the light) may hold a point of the
// tile: the region lies inside the two planes through the edge tangent to the light and one
// plane at each end, tested against the tile's pixel box and z-min/z-max (the 2004 paper's
// tile culling, section 4). Conservative by `margin_footprints` pixel footprints, so a shaded
// point that sits that far off the depth-buffer point (the oracle's ray origin does,
// reference/ray_origin.h) still finds its edges.
struct EdgeBins {
  int level = 3;
  int columns = 0, rows = 0;
  std::vector<uint32_t> begin;  // per tile, into `edges`; one extra entry at the end
  std::vector<uint32_t> edges;  // edge indices, ascending within a tile
  // Per potential edge, its planes for the per-pixel quick reject (edge_screen_test.h).
  std::vector<EdgeScreenTest> tests;
  // margin_footprints pixel footprints over w, the quick reject's offset for a pixel whose
  // shaded point is not known yet, and the tiles' (PixelBlock::offset).
  float offset = 0.0f;
  // The same for the triangles cutting the light (PotentialEdges::cutting): per tile, indices,
  // and per triangle its region's planes for the quick reject (no silhouette test).
  std::vector<uint32_t> cutting_begin, cutting;
  std::vector<EdgeScreenTest> cutting_tests;
  uint64_t tiles_tested = 0, tiles_culled = 0;
};

// One bin tile: its edges and its pixels [x0, x1) x [y0, y1) in a width x height view.
struct EdgeBinTile {
  const uint32_t* begin;
  const uint32_t* end;
  int x0, x1, y0, y1;
};
inline EdgeBinTile edgeBinTile(const EdgeBins& bins, size_t index, int width, int height) {
  const int tile = 1 << bins.level;
  const int tx = int(index % size_t(bins.columns)), ty = int(index / size_t(bins.columns));
  const int x0 = tx * tile, y0 = ty * tile;
  return EdgeBinTile{bins.edges.data() + bins.begin[index],
                     bins.edges.data() + bins.begin[index + 1], x0, std::min(width, x0 + tile),
                     y0, std::min(height, y0 + tile)};
}
// Adds to every pixel of `layer` (the view's size) the count of potential edges binned at its
// tile: where the edges' regions of influence reach after the tile test, the wedge footprints
// of the exact technique (its kWedgeFootprintsLayer debug layer).
void addBinnedEdgeCounts(const EdgeBins& bins, Image<float>& layer);

// The depth parts of the tiles of 2^level pixels (EdgeTileParts) for the tile test.
TileDepthParts tileDepthParts(const DepthBuffer& depth, int level);

// `scene_bounds`, when not empty, holds every visible point (Scene::bounds): the regions are cut
// off where they leave it (widened by the margin), which keeps a shadow's streak toward its
// vanishing point from reaching across the screen. A region's tiles are tested hierarchically:
// first coarse tiles of 2^coarse_step x 2^coarse_step bin tiles, each the hull of their pixel
// boxes and depth parts, then the bin tiles of the coarse tiles kept. The coarse test is the
// same float test on a box holding the bin tiles' boxes, so it culls only coarse tiles none of
// whose bin tiles would be kept: the bins and their counters are those of the flat scan
// (coarse_step 0), which the tests check.
inline constexpr int kCoarseTileStep = 2;
EdgeBins binEdges(const PotentialEdges& edges, const Light& light, const View& view,
                  const DepthBuffer& depth, int level, double margin_footprints,
                  const Bounds3& scene_bounds = Bounds3(), bool simd = true,
                  int coarse_step = kCoarseTileStep);

}  // namespace penumbra
