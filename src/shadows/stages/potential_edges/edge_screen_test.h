#pragma once
// The per-pixel quick reject of the exact soft shadow volumes, one edge against a block of 64
// pixels at a time: before the exact test in double (exact_technique.cpp), the pixel's
// depth-buffer point is put in float into the edge's region planes and its triangles' planes
// (potential_edges.h, binEdges), screen-space forms set up once per edge (wedge_screen.h: the
// world plane value over w). A pixel is kept when it may lie in the region and may see the edge
// as a silhouette: every plane within its margin of the point. The margin is the plane's own
// float rounding (EdgeScreenTest) plus the pixel's `offset` (PixelBlock): how far the shaded
// point can lie from the depth-buffer point, in the same units (world distance over w).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra {

inline constexpr int kBlockPixels = 64;
// Tangent planes, end planes and a circumscribed pyramid (potential_edges.cpp).
inline constexpr int kMaxRegionPlanes = 8;

// E(sx, sy, z) = ((a sx + b sy) + c z) + d, in float, in this order. The margins bound its float
// rounding at any pixel centre of the image with z in [0, 1]; a point is within a plane's
// margin where E >= -(margin + offset), offset the pixel's (or the tile row's).
//
// Laid out by how often it is read: the quick reject reads a tile's edges once per block of
// 64 pixels, from records spread over the whole mesh, and was bound by fetching them. Its
// first cache line holds the counts, signs, weights and every margin, the next two the region
// planes, the fourth the triangles' planes; what only a triangle cutting the light needs comes
// after, fetched when one does (four lines of six for the usual edge).
struct alignas(64) EdgeScreenTest {
  int8_t region_count = 0;
  // Triangles: a sign is known where |E| > margin + offset; included (crossed between point
  // and light) where that sign is not the light centre's; an included triangle adds `weight`
  // (+-1).
  int8_t triangle_count = 0;  // 0: no silhouette test (more than 4 triangles)
  bool any_cuts = false;      // one of cuts[0 .. triangle_count)
  int8_t weight[4] = {};
  bool light_above[4] = {};
  bool cuts[4] = {};
  float region_margin[kMaxRegionPlanes];
  float triangle_margin[4];
  float region[kMaxRegionPlanes][4];
  float triangle[4][4];
  // A triangle whose plane cuts the light (`cuts`) is included, on either side, where its part
  // toward the light lies wholly in front of the light (pixel_edges.h, classifyCutting), and
  // adds `weight` on its positive side, -`weight` on its negative side; elsewhere it is not
  // counted, so the pixel is kept unless the test below proves that. Its corners relative to
  // the light centre c, v' = v - c, are in front of the light seen from a point p when
  // v'.q + r |q| < 0 for q = c - p (the corner's depth along the axis below |q| - r); the
  // pixel's PixelBlock::reach and ::slack widen that (cutInFront).
  float ends[2][3];        // the edge's corners a', b'
  float opposite[4][3];    // each triangle's third corner
  float cut_extent[4];     // the largest |v'| of the triangle's corners plus r, rounded up
};
// The lines every quick reject of an edge may read (all but the cutting triangles' part).
inline constexpr size_t kEdgeTestHotBytes = offsetof(EdgeScreenTest, ends);
static_assert(offsetof(EdgeScreenTest, triangle_margin) + 4 * sizeof(float) <= 64,
              "the counts, signs, weights and margins share the first cache line");
static_assert(kEdgeTestHotBytes == 4 * 64, "the planes fill the next three lines");

// Up to 64 pixels: screen position of the centre and stored depth; `active` has bit i set for
// the pixels to test. For the cutting triangles' test, per pixel q = c - p0 from its
// depth-buffer point p0, `reach` = r |q| + eps |q|^2 and `slack` = d + eps |q|, d the farthest
// the shaded point lies from p0 (a move of p by d changes v'.q + r |q| by at most
// d (|v'| + r)) and eps far above the float rounding of these values (exact_technique.cpp): a
// corner is certainly in front where v'.q + reach + slack * (|v'| + r) < 0.
// `offset` is the farthest the pixel's shaded point lies from its depth-buffer point, over the
// point's w: the largest possible before the shaded point is known (EdgeBins::offset), the
// distance itself, rounded up, once it is. The shaded point is the depth-buffer point's
// closest point on the visible triangle, lifted off it by float rounding (ray_origin.h), so
// the depth-buffer point lies within its offset (and the lift, far inside the planes' rounding
// margins) of that triangle's plane: the visible triangle, which the exact test leaves out of
// the weight, never has a sign here either.
struct alignas(64) PixelBlock {
  float sx[kBlockPixels], sy[kBlockPixels], z[kBlockPixels];
  float offset[kBlockPixels];
  float qx[kBlockPixels], qy[kBlockPixels], qz[kBlockPixels];
  float reach[kBlockPixels], slack[kBlockPixels];
  bool has_q = false;  // false: q, reach and slack unset, every cutting triangle keeps the pixel
  uint64_t active = 0;
};

// Bit i set: pixel i is active and may need the exact test.
uint64_t edgeCandidates(const EdgeScreenTest& test, const PixelBlock& block, bool simd);
uint64_t edgeCandidatesScalar(const EdgeScreenTest& test, const PixelBlock& block);

// The same reject for whole tiles (edge_bins.cpp): square tiles of `size` pixels, tiles
// [tx0, tx1] x [ty0, ty1] of a grid of `columns`, tile (tx, ty) holding the pixel centres
// [tx size + 0.5, min(tx size + size, width) - 0.5] x [ty size + 0.5, min(ty size + size,
// height) - 0.5] and its depth-buffer points' reversed-Z range [zmin, zmax] (entry ty columns +
// tx; zmax 0: only background, nothing to shade). A tile is kept unless the box of those ranges
// lies outside a region plane by more than its margin, or the edge's triangles' planes each
// have one sign over the box (no triangle cutting the light) and their weights cancel: the
// pixel test's float operations at the box corner that decides each bound, so a kept pixel's
// tile is kept. (A point on one of the edge's triangles is on its plane, so the visible
// triangle, which the pixels leave out of the weight, never has a sign over a box holding the
// point.) SIMD over 4 to 16 tiles of a row with a scalar twin (same results).
// Both arrays must be readable kTileBoxPadding entries past the last tile of the grid (the
// SIMD twin loads whole vectors of a row and masks off the lanes past the box).
inline constexpr int kTileBoxPadding = 16;
//
// Optionally (parts non-null), per tile its surface pixels' depths in two parts, split at the
// middle of their range (tileDepthParts), each part's [zmin, zmax] (zmax 0: no pixel in it).
// A tile is then kept where one part passes (a pixel's depth lies in one of them; a part that
// passes implies the whole range would, so that test is left out). A tile showing an object's
// edge over a far surface has a range holding both, and the box between them meets regions no
// pixel of it is in (on dragon-res2, 45 % of the (edge, tile) pairs handed out, and 11 % of
// those with a candidate pixel, were on tiles whose depths spread over more than a fifth of
// their range).
struct EdgeTileParts {
  const float* low_zmin;
  const float* low_zmax;
  const float* high_zmin;
  const float* high_zmax;
};
struct EdgeTileBox {
  const float* zmin;
  const float* zmax;
  int columns;
  int tx0, tx1, ty0, ty1;
  int size, width, height;
  float offset;  // the largest PixelBlock::offset of any pixel (EdgeBins::offset)
  const EdgeTileParts* parts = nullptr;
};
// The parts of every tile of 2^level pixels of `depth` (surface pixels only: depth > 0): the
// four arrays of EdgeTileParts, a tile per entry (row-major, `columns` per row) and
// kTileBoxPadding zero entries past the last.
struct TileDepthParts {
  std::vector<float> low_zmin, low_zmax, high_zmin, high_zmax;
  EdgeTileParts view() const {
    return {low_zmin.data(), low_zmax.data(), high_zmin.data(), high_zmax.data()};
  }
};
// Writes the kept tiles' indices (ty columns + tx) to `kept` (room for the box's tiles) in
// ascending order and returns their number; `tested` gets the number of tiles that hold a
// covered pixel.
int edgeTileCandidates(const EdgeScreenTest& test, const EdgeTileBox& box, uint32_t* kept,
                       int& tested, bool simd);
int edgeTileCandidatesScalar(const EdgeScreenTest& test, const EdgeTileBox& box, uint32_t* kept,
                             int& tested);

}  // namespace penumbra
