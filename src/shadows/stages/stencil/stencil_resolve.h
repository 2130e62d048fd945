#pragma once
// The resolve of a hard shadow stencil, a row at a time (facing_away.h's rule with "lit where the
// stencil is 0"): 1 on the background, 0 where the visible triangle faces away from the light,
// else 1 where the stencil is 0 and 0 where it is not. A SIMD version (Highway, dispatched at run
// time) and its scalar twin give identical rows. The SIMD one decides a vector of pixels showing
// one triangle with one facing lookup (most vectors, away from silhouettes and small triangles)
// and the others lane by lane.
#include <cstddef>
#include <cstdint>

#include "shadows/stages/silhouettes/facing_away.h"

namespace penumbra {

// A piece of a block's rows: columns [x0, x0 + n) resolved from `stencil` (its rows
// `stencil_stride` elements apart, from the block's first row), or with stencil 0 where it is
// null (nothing drawn there).
struct StencilSegment {
  int x0 = 0, n = 0;
  const int32_t* stencil = nullptr;
  size_t stencil_stride = 0;
};

// `rows` rows of out from ids (the eye pass's primitive ids), each with its own stride in
// elements between rows, every row resolved segment by segment, left to right: a row of bin
// tiles of frame-sized images, its tiles' stencils in copies of their own or none, in one call
// (one dispatch for the block, not one per piece).
struct StencilResolveRows {
  const uint32_t* ids = nullptr;
  size_t ids_stride = 0;
  float* out = nullptr;
  size_t out_stride = 0;
  int rows = 0;
  const StencilSegment* segments = nullptr;
  size_t count = 0;
};
void resolveStencilRows(const FacingAway& away, const StencilResolveRows& block, bool simd);
void resolveStencilRowsScalar(const FacingAway& away, const StencilResolveRows& block);

// One row: out[0, n) from ids[0, n) and stencil[0, n).
inline void resolveStencilRow(const FacingAway& away, const uint32_t* ids, const int32_t* stencil,
                              float* out, int n, bool simd) {
  const StencilSegment segment{0, n, stencil, 0};
  resolveStencilRows(away, {ids, 0, out, 0, 1, &segment, 1}, simd);
}

}  // namespace penumbra
