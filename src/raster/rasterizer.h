#pragma once
// The two passes built on the tile kernels: depth (eye pass) and stencil (shadow volumes).
#include <cstdint>
#include <functional>
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "raster/depth_buffer.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// Draws `triangles` into depth (reversed-Z) and primitive ids (payload), sized alike, closest
// wins, ties keep the earlier triangle. Every pixel is written: where no triangle covers it,
// depth 0 (background) and kNoPrimitive. Counts pixels_rasterized,
// z_reads and stencil_writes (here: depth writes) and triangles.
void rasterizeDepth(const ClipTriangles& triangles, Image<float>& depth,
                    Image<uint32_t>& primitive, Stats& stats, bool simd);
// The same into depth.depth, and depth's tile ranges as DepthBuffer::buildTileRanges builds
// them, taken from each bin tile while it is in cache (no second pass over the buffer).
void rasterizeDepth(const ClipTriangles& triangles, DepthBuffer& depth,
                    Image<uint32_t>& primitive, Stats& stats, bool simd);

struct StencilOptions {
  bool simd = true;
  // Skip (triangle, bin tile) pairs that the tile's z-min/z-max prove cannot pass the depth
  // rule: z-pass needs the triangle in front of some pixel, z-fail behind or at some pixel.
  // Only work counters change with it, never the stencil.
  bool tile_culling = true;
  int cull_level = 5;  // culling tiles of 2^cull_level pixels (1..8); 5 = the bin tiles
  // With tile_culling: a polygon that covers a whole culling tile and passes the depth rule at
  // every pixel of it (z-min and z-max prove it) adds to one coarse value per tile instead of
  // to each pixel (the z-min trivial accept of Aila's 2005 thesis, section 1.5, into the
  // two-level storage its section 4.3 proposes; raster/tile_offsets.h). The
  // stencil ends the same; z_reads and stencil_writes fall, tiles_accepted counts such tiles.
  bool two_level = true;
  // The eye pass's primitive ids, needed when polygons have owners (ClipTriangles::owners):
  // they are not counted at their owners' pixels. Null: owners are ignored.
  const Image<uint32_t>* primitive = nullptr;
  // A debug layer that counts the culled tiles per pixel (CullTally::culled_layer); null: none.
  Image<float>* culled_layer = nullptr;
};

// Adds every triangle's contribution to the stencil where its depth rule holds. The payload is
// a signed multiplicity w for a volume polygon whose front side faces out of the volume; the
// added value is w for front-facing / -w for back-facing with z-pass, negated with z-fail
// (flag kZFail), so a pixel's sum counts the volumes its point is inside. The stencil must be
// sized like the depth and all zero (the caller clears it; tiles are counted from zero in
// copies of their own, which are stored back, so earlier contents would be lost).
void rasterizeStencil(const ClipTriangles& triangles, const DepthBuffer& depth,
                      Image<int32_t>& stencil, Stats& stats, const StencilOptions& options);
// The same for triangles set up already (setupTriangles), which the caller counted.
void rasterizeStencil(const std::vector<SetupTriangle>& setup, const DepthBuffer& depth,
                      Image<int32_t>& stencil, Stats& stats, const StencilOptions& options);
// What rasterizeStencil adds at pixel (x, y) for the set-up polygon t (`primitive`: the ids of
// StencilOptions::primitive, or null): the same edge functions, the same float depth stepped
// from the bin tile's corner and the same depth rule and owners, so a pass that needs to know
// whether the stencil counted a polygon at a pixel gets the stencil's own decision.
int32_t stencilContributionAt(const SetupTriangle& t, int x, int y, const DepthBuffer& depth,
                              const Image<uint32_t>* primitive);

// The tile loop the passes above are built on, for passes with their own pixel kernels (penumbra
// wedges): sets up `triangles`, bins those keep(triangle) accepts (a pass that draws only some,
// such as front-facing wedge faces, bins only those), then calls visit(tile) for every bin tile
// that holds a triangle, on the worker owning that tile. visit may only write pixels of its
// tile.
class TileTriangles {
 public:
  TileTriangles(size_t index, const TileBox& box, const std::vector<SetupTriangle>& setup,
                const uint32_t* begin, const uint32_t* end)
      : index_(index), box_(box), setup_(&setup), begin_(begin), end_(end) {}
  size_t index() const { return index_; }  // bin tile index, row-major
  const TileBox& box() const { return box_; }
  // fn(triangle, rect) for the tile's triangles in input order; `rect` comes from setupTileRect:
  // fn sets up the edges (setupRectEdges, or forEachCullRect after its culling pre-test).
  template <class Fn>
  void forEach(Fn&& fn) const {
    for (const uint32_t* k = begin_; k != end_; ++k) {
      const SetupTriangle& t = (*setup_)[*k];
      TileEdges e;
      if (setupTileRect(t, box_.x0, box_.y0, box_.x1, box_.y1, e)) fn(t, e);
    }
  }

 private:
  size_t index_;
  TileBox box_;
  const std::vector<SetupTriangle>* setup_;
  const uint32_t *begin_, *end_;
};
void forEachBinTile(const ClipTriangles& triangles, int width, int height,
                    const std::function<bool(const SetupTriangle&)>& keep,
                    const std::function<void(const TileTriangles&)>& visit, Stats& stats);
// The same for triangles set up (and kept) already; `setup` must outlive the call.
void forEachBinTile(const std::vector<SetupTriangle>& setup, int width, int height,
                    const std::function<void(const TileTriangles&)>& visit);

}  // namespace penumbra
