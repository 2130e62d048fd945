#pragma once
// Draws occluders into the occlusion buffer of the object-level culler (raster/occlusion_culler.h)
// with the eye pass's own setup, binning and depth kernel, onto what earlier batches drew.
#include <cstdint>

#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// A cleared occlusion buffer of the given size: depth 0 (background) everywhere, tile ranges
// allocated and 0.
void clearOcclusionBuffer(DepthBuffer& occlusion, int width, int height);

// Adds `triangles` to `occlusion` (closest wins) and updates the tile ranges of the bin tiles
// they reach and the levels above. Every pixel depth it stores is the one the eye pass computes
// for the same triangle at that pixel (same setup, tiles and kernel), so the buffer never holds a
// surface closer than the eye pass's final depth. Returns the triangles set up.
uint64_t drawOccluders(const ClipTriangles& triangles, DepthBuffer& occlusion, bool simd);

}  // namespace penumbra
