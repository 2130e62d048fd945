#include "shadows/stages/stencil/stencil_resolve.h"

namespace penumbra {

void resolveStencilRowsScalar(const FacingAway& away, const StencilResolveRows& block) {
  for (int y = 0; y < block.rows; ++y)
    for (size_t k = 0; k < block.count; ++k) {
      const StencilSegment& g = block.segments[k];
      const uint32_t* ids = block.ids + size_t(y) * block.ids_stride + g.x0;
      const int32_t* stencil =
          g.stencil != nullptr ? g.stencil + size_t(y) * g.stencil_stride : nullptr;
      float* out = block.out + size_t(y) * block.out_stride + g.x0;
      for (int x = 0; x < g.n; ++x)
        out[x] = resolvedPixel(
            away, ids[x], [&] { return stencil != nullptr && stencil[x] != 0 ? 0.0f : 1.0f; });
    }
}

}  // namespace penumbra
