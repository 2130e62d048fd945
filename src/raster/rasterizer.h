#pragma once
// The two passes built on the tile kernels: depth (eye pass) and stencil (shadow volumes).
#include <cstdint>

#include "core/image.h"
#include "core/stats.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// Draws `triangles` into depth (reversed-Z, cleared to 0 by the caller) and primitive ids
// (payload), closest wins, ties keep the earlier triangle. Counts pixels_rasterized,
// z_reads and stencil_writes (here: depth writes) and triangles.
void rasterizeDepth(const ClipTriangles& triangles, Image<float>& depth,
                    Image<uint32_t>& primitive, Stats& stats, bool simd);

struct StencilOptions {
  bool simd = true;
  // Skip (triangle, bin tile) pairs that the tile's z-min/z-max prove cannot pass the depth
  // rule: z-pass needs the triangle in front of some pixel, z-fail behind or at some pixel.
  // Only work counters change with it, never the stencil.
  bool tile_culling = true;
};

// Adds every triangle's contribution to the stencil where its depth rule holds. The payload is
// a signed multiplicity w for a volume polygon whose front side faces out of the volume; the
// added value is w for front-facing / -w for back-facing with z-pass, negated with z-fail
// (flag kZFail), so a pixel's sum counts the volumes its point is inside. The stencil must be
// sized like the depth and cleared by the caller.
void rasterizeStencil(const ClipTriangles& triangles, const DepthBuffer& depth,
                      Image<int32_t>& stencil, Stats& stats, const StencilOptions& options);

}  // namespace penumbra
