#pragma once
// The resolve of a hard shadow stencil, a row at a time (facing_away.h's rule with "lit where the
// stencil is 0"): 1 on the background, 0 where the visible triangle faces away from the light,
// else 1 where the stencil is 0 and 0 where it is not. A SIMD version (Highway, dispatched at run
// time) and its scalar twin give identical rows. The SIMD one decides a vector of pixels showing
// one triangle with one facing lookup (most vectors, away from silhouettes and small triangles)
// and the others lane by lane.
#include <cstdint>

#include "shadows/facing_away.h"

namespace penumbra {

// out[0, n) from ids[0, n) (the eye pass's primitive ids) and stencil[0, n); a null stencil is
// all 0 (nothing drawn there).
void resolveStencilRow(const FacingAway& away, const uint32_t* ids, const int32_t* stencil,
                       float* out, int n, bool simd);
void resolveStencilRowScalar(const FacingAway& away, const uint32_t* ids, const int32_t* stencil,
                             float* out, int n);

}  // namespace penumbra
