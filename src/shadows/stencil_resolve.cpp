#include "shadows/stencil_resolve.h"

namespace penumbra {

void resolveStencilRowsScalar(const FacingAway& away, const StencilResolveRows& block) {
  for (int y = 0; y < block.rows; ++y) {
    const uint32_t* ids = block.ids + size_t(y) * block.ids_stride;
    const int32_t* stencil =
        block.stencil != nullptr ? block.stencil + size_t(y) * block.stencil_stride : nullptr;
    float* out = block.out + size_t(y) * block.out_stride;
    for (int x = 0; x < block.n; ++x)
      out[x] = resolvedPixel(away, ids[x],
                             [&] { return stencil != nullptr && stencil[x] != 0 ? 0.0f : 1.0f; });
  }
}

}  // namespace penumbra
