#pragma once
// The shadow mask's per-(triangle, tile) pixel kernel: the double or halve blend of one shadow
// volume polygon (mask_values.h) where it passes the depth rule, in place of the stencil
// kernel's add (raster/tile_kernels.h). SIMD (Highway) with a scalar twin that takes the same
// steps; the two give bit-identical masks and counts.
#include <cstdint>

#include "raster/tile_kernels.h"

namespace penumbra {

// How a mask buffer holds its 8-bit value: the alpha channel alone (one byte per pixel, the
// scene's RGB lying elsewhere), or the screen buffer's RGBA8 pixels with R = G = B = the mask
// (the paper's grey blend brightness acts on the three channels alike) and A unused, 0.
enum class MaskLayout : uint8_t { Alpha8, Rgba8 };
inline int maskBytesPerPixel(MaskLayout layout) { return layout == MaskLayout::Alpha8 ? 1 : 4; }

// Where the kernel reads and writes: a bin tile's own copies (raster/tile_copy.h), pixel (x, y)
// of the image at element (y - y0) * stride + (x - x0); the mask's element is
// maskBytesPerPixel bytes. The SIMD kernel reads and writes back up to one vector of pixels
// past a row's last covered one (unchanged): the mask buffer needs kMaskKernelPadding bytes
// past its last pixel.
struct MaskTarget {
  const float* depth;
  uint8_t* mask;
  int stride;
  int x0 = 0, y0 = 0;
  MaskLayout layout = MaskLayout::Alpha8;
  // One byte per pixel, at the depth's element: set to 1 where a halving lost a power of two
  // (maskHalvingLoses). The SIMD kernel touches only written pixels' bytes.
  uint8_t* saturated = nullptr;
};
inline constexpr int kMaskKernelPadding = 64;

// One polygon's blend: `steps` doublings (saturating at 255) or halvings (rounding up), 1 to
// kMaskMaxSteps, at covered pixels with a surface where the depth rule holds. Counts covered
// pixels (each reads the depth once) and pixels written, as the stencil kernel does. Returns the
// number of pixels whose halving lost a power of two (each also flagged in target.saturated).
struct MaskBlend {
  bool doubles = true;
  int steps = 1;
};
uint64_t maskKernel(const TileEdges& e, MaskBlend blend, DepthRule rule,
                    const MaskTarget& target, KernelCounts& counts, bool simd);
uint64_t maskKernelScalar(const TileEdges& e, MaskBlend blend, DepthRule rule,
                      const MaskTarget& target, KernelCounts& counts);

}  // namespace penumbra
