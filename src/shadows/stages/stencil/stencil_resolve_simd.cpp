// SIMD twin of stencil_resolve.cpp's rows, compiled once per CPU target by Highway and chosen at
// run time (HWY_DYNAMIC_DISPATCH). Same rule, same results.
#include <algorithm>

#include "core/simd_dispatch.h"
#include "shadows/stages/stencil/stencil_resolve.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/stages/stencil/stencil_resolve_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ResolveStencilRow(const FacingAway& away, const uint32_t* ids, const int32_t* stencil,
                       float* out, int n) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
  const size_t lanes = hn::Lanes(df);
  const auto one = hn::Set(df, 1.0f);
  constexpr size_t kAhead = 128;  // pixels
  for (size_t x = 0; x < size_t(n); x += lanes) {
    const size_t count = std::min(lanes, size_t(n) - x);
    // The rows are read once, left to right: asked for ahead (as the shading kernel does).
    if (x + kAhead < size_t(n)) {
      __builtin_prefetch(ids + x + kAhead);
      if (stencil != nullptr) __builtin_prefetch(stencil + x + kAhead);
    }
    const auto in_row = hn::FirstN(du, count);
    const auto id = hn::MaskedLoad(in_row, du, ids + x);
    // Lit by the stencil: 1 where it is 0.
    auto lit = one;
    if (stencil != nullptr) {
      const auto s = hn::MaskedLoad(hn::RebindMask(di, in_row), di, stencil + x);
      lit = hn::IfThenElseZero(hn::RebindMask(df, hn::Eq(s, hn::Zero(di))), one);
    }
    const uint32_t first = ids[x];
    hn::Vec<decltype(df)> result;
    if (hn::AllTrue(du, hn::Or(hn::Eq(id, hn::Set(du, first)), hn::Not(in_row)))) {
      // One triangle (or the background) under every lane: one facing decision.
      result = first == kNoPrimitive ? one : (away(first) ? hn::Zero(df) : lit);
    } else {
      alignas(HWY_MAX_BYTES) float lanes_out[kMaxLanes];
      hn::Store(lit, df, lanes_out);
      for (size_t i = 0; i < count; ++i) {
        const uint32_t p = ids[x + i];
        if (p == kNoPrimitive) {
          lanes_out[i] = 1.0f;
        } else if (away(p)) {
          lanes_out[i] = 0.0f;
        }
      }
      result = hn::Load(df, lanes_out);
    }
    // Whole vectors are stored plainly; only the row's last, partial vector needs the mask.
    if (count == lanes) {
      hn::StoreU(result, df, out + x);
    } else {
      hn::BlendedStore(result, hn::RebindMask(df, in_row), df, out + x);
    }
  }
}

void ResolveStencilRowsSimd(const FacingAway& away, const StencilResolveRows& block) {
  for (int y = 0; y < block.rows; ++y)
    for (size_t k = 0; k < block.count; ++k) {
      const StencilSegment& g = block.segments[k];
      ResolveStencilRow(away, block.ids + size_t(y) * block.ids_stride + g.x0,
                        g.stencil != nullptr ? g.stencil + size_t(y) * g.stencil_stride
                                             : nullptr,
                        block.out + size_t(y) * block.out_stride + g.x0, g.n);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(ResolveStencilRowsSimd);

void resolveStencilRows(const FacingAway& away, const StencilResolveRows& block, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(ResolveStencilRowsSimd)(away, block);
  } else {
    resolveStencilRowsScalar(away, block);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void resolveStencilRows(const FacingAway& away, const StencilResolveRows& block, bool) {
  resolveStencilRowsScalar(away, block);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
