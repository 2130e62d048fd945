#pragma once
// The pixel kernel of wedge rasterization (2004 paper, sections 3 and 6): for every pixel a
// wedge triangle covers, one depth read, then optionally the umbra contribution of a front
// plane (depth-tested, +-255 per unit, rasterizeUmbra) and optionally the penumbra
// contribution (is the depth-buffer point inside the wedge? then add round(255 s),
// rasterizePenumbra). The three-pass implementation uses it with one part at a time, the
// single-pass implementation with both (section 6.2). A SIMD version (Highway) and a scalar
// twin with the same steps give identical LI buffers and counts.
#include <cstddef>
#include <cstdint>

#include "raster/tile_kernels.h"
#include "shadows/wedge/li_buffer.h"
#include "shadows/wedge/wedge_screen.h"

namespace penumbra {

// Where the kernels read depth and add to the LI buffer: pixel (x, y) of the image is element
// (y - y0) * stride + (x - x0), the whole image or one tile's copy (raster/tile_copy.h).
struct WedgeKernelTarget {
  const float* depth;
  int16_t* li;
  int stride;
  int x0 = 0, y0 = 0;
  size_t index(int x, int y) const {
    return size_t(y - y0) * size_t(stride) + size_t(x - x0);
  }
};

struct WedgeKernelWork {
  // Umbra: add umbra_value where the triangle's depth passes `rule` against the stored depth
  // (0: no umbra part). Penumbra: the wedge whose inside to test (null: no penumbra part).
  int32_t umbra_value = 0;
  DepthRule rule = DepthRule::Closer;
  const ScreenWedge* wedge = nullptr;
  float li_scale = 255.0f;  // LI units of a fully visible light (255, or 255 / n lights)
};

struct WedgeKernelCounts {
  uint64_t covered = 0;  // pixels inside the triangle: each is one depth read
  uint64_t writes = 0;   // LI writes: pixels that received an umbra or penumbra contribution
  uint64_t inside = 0;   // pixels whose depth point lies inside the wedge (penumbra part)
};

void wedgeKernel(const TileEdges& e, const WedgeKernelWork& work, const WedgeKernelTarget& target,
                 WedgeKernelCounts& counts, bool simd);
void wedgeKernelScalar(const TileEdges& e, const WedgeKernelWork& work,
                       const WedgeKernelTarget& target, WedgeKernelCounts& counts);

}  // namespace penumbra
