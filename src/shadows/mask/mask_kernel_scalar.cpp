// Scalar twin of mask_kernel_simd.cpp, also used by the scalar-only build.
#include "shadows/mask/mask_kernel.h"
#include "shadows/mask/mask_values.h"

namespace penumbra {

uint64_t maskKernelScalar(const TileEdges& e, MaskBlend blend, DepthRule rule,
                      const MaskTarget& target, KernelCounts& counts) {
  const int bytes = maskBytesPerPixel(target.layout);
  uint64_t lost = 0;
  // Covered: inside all three edges (>= 0).
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    // Depth rule against the stored depth, only where there is a surface (stored depth > 0).
    const size_t i = size_t(y - target.y0) * size_t(target.stride) + size_t(x - target.x0);
    const float stored = target.depth[i];
    const float d = triangleDepthAt(e, x, y);
    const bool pass = rule == DepthRule::Closer ? d > stored : d <= stored;
    if (!(stored > 0.0f && pass)) return;
    // The blend on the pixel's 8-bit value; with RGBA8 on R, G and B alike.
    uint8_t* p = target.mask + i * size_t(bytes);
    const uint32_t v = p[0];
    if (!blend.doubles && maskHalvingLoses(v, blend.steps)) {
      ++lost;
      target.saturated[i] = 1;
    }
    const uint8_t w = uint8_t(blend.doubles ? maskDouble(v, blend.steps) : maskHalve(v, blend.steps));
    p[0] = w;
    if (target.layout == MaskLayout::Rgba8) p[1] = p[2] = w;
    ++counts.writes;
  });
  return lost;
}

}  // namespace penumbra
