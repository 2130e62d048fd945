#pragma once
// The eye pass's depth rasterization with its options: a delay stream between the triangles and
// the pixels (raster/delay_stream.h), and the depth-complexity counters.
#include <cstddef>
#include <cstdint>

#include "core/image.h"
#include "core/stats.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"

namespace penumbra {

struct DepthPassOptions {
  bool simd = true;
  // The ring of a delay stream, in bytes; 0: none. The buffers are the same with any ring;
  // fewer pixels are rasterized, and the stream's counters are counted.
  size_t delay_stream_bytes = 0;
  // Count eye_depth_passes and eye_covered_pixels (delay_stream.h); always with a stream.
  bool depth_complexity = false;
};

// rasterizeDepth (raster/rasterizer.h) into depth.depth and its tile ranges, with `options`.
void rasterizeDepth(const ClipTriangles& triangles, DepthBuffer& depth,
                    Image<uint32_t>& primitive, Stats& stats, const DepthPassOptions& options);

}  // namespace penumbra
