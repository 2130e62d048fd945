#include "shadows/stencil_resolve.h"

namespace penumbra {

void resolveStencilRowScalar(const FacingAway& away, const uint32_t* ids, const int32_t* stencil,
                             float* out, int n) {
  for (int x = 0; x < n; ++x)
    out[x] = resolvedPixel(away, ids[x],
                           [&] { return stencil != nullptr && stencil[x] != 0 ? 0.0f : 1.0f; });
}

}  // namespace penumbra
