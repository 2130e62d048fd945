// SIMD twin of mask_kernel_scalar.cpp, compiled once per CPU target by Highway and chosen at run
// time (HWY_DYNAMIC_DISPATCH). Same steps and integer operations, same results. The pixel walk
// is the stencil kernel's (raster/tile_kernels_simd.cpp): rows from RowSpans, their spans a
// batch at a time (raster/row_spans_simd-inl.h), edge values stepped per vector, the depth rule
// in float lanes; the 8-bit values are widened to 32-bit lanes for the blend and narrowed back.
#include "shadows/mask/mask_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/mask/mask_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

#include "raster/row_spans_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Flags the written lanes whose halving loses a power of two (mask_values.h: maskHalvingLoses);
// returns how many. Rare (only past the 8 bits' headroom), so the flags are set lane by lane.
template <class DI>
uint64_t FlagLostHalvings(DI di, hn::Vec<DI> old, hn::Mask<DI> write, int steps,
                          uint8_t* saturated) {
  const auto one = hn::Set(di, 255);  // acting as 256
  const auto value = hn::Add(old, hn::IfThenElseZero(hn::Eq(old, one), hn::Set(di, 1)));
  const auto lost = hn::And(write, hn::Lt(value, hn::Set(di, 1 << steps)));
  if (hn::AllFalse(di, lost)) return 0;
  HWY_ALIGN int32_t flags[hn::MaxLanes(di)];
  hn::Store(hn::IfThenElseZero(lost, hn::Set(di, 1)), di, flags);
  for (size_t lane = 0; lane < hn::Lanes(di); ++lane)
    if (flags[lane] != 0) saturated[lane] = 1;
  return hn::CountTrue(di, lost);
}

// One vector of pixels' blend at the lanes in `write`, pixel `pixel` of the target the first
// lane's; returns the lanes whose halving lost a power of two.
template <class DI>
uint64_t BlendPixels(DI di, hn::Mask<DI> write_i, size_t pixel, MaskBlend blend,
                     const MaskTarget& target) {
  const hn::RebindToUnsigned<DI> du;
  const hn::Rebind<uint8_t, DI> d8;
  const int steps = blend.steps;
  // mask_values.h: maskDouble / maskHalve.
  const auto apply = [&](hn::Vec<DI> v) {
    return blend.doubles ? hn::Min(hn::ShiftLeftSame(v, steps), hn::Set(di, 255))
                         : hn::ShiftRightSame(hn::Add(v, hn::Set(di, (1 << steps) - 1)), steps);
  };
  uint64_t lost = 0;
  if (target.layout == MaskLayout::Rgba8) {
    // R = G = B = the mask, A kept: one 32-bit pixel per lane.
    uint32_t* p = reinterpret_cast<uint32_t*>(target.mask) + pixel;
    const auto write_u = hn::RebindMask(du, write_i);
    const auto old = hn::MaskedLoad(write_u, du, p);
    const auto old_i = hn::BitCast(di, hn::And(old, hn::Set(du, 0xffu)));
    if (!blend.doubles) lost = FlagLostHalvings(di, old_i, write_i, steps, target.saturated + pixel);
    const auto v = hn::BitCast(du, apply(old_i));
    const auto grey = hn::Or(v, hn::Or(hn::ShiftLeft<8>(v), hn::ShiftLeft<16>(v)));
    hn::BlendedStore(hn::Or(hn::AndNot(hn::Set(du, 0xffffffu), old), grey), write_u, du, p);
  } else {
    // The whole vector of bytes is read and written back, unchanged where not written (the
    // buffer's padding covers a vector past the tile's last pixel).
    uint8_t* p = target.mask + pixel;
    const auto old = hn::PromoteTo(di, hn::LoadU(d8, p));
    if (!blend.doubles) lost = FlagLostHalvings(di, old, write_i, steps, target.saturated + pixel);
    hn::StoreU(hn::DemoteTo(d8, hn::IfThenElse(write_i, apply(old), old)), d8, p);
  }
  return lost;
}

uint64_t MaskKernelSimd(const TileEdges& e, MaskBlend blend, DepthRule rule,
                        const MaskTarget& target, KernelCounts& counts) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const int lanes = int(hn::Lanes(df));
  const auto iota_i = hn::Iota(di, 0);
  const hn::Vec<decltype(di)> lane_step[3] = {hn::Mul(hn::Set(di, e.dx[0]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[1]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[2]), iota_i)};
  const hn::Vec<decltype(di)> vector_step[3] = {hn::Set(di, e.dx[0] * lanes),
                                                hn::Set(di, e.dx[1] * lanes),
                                                hn::Set(di, e.dx[2] * lanes)};
  const auto minus_one = hn::Set(di, -1);
  const auto da = hn::Set(df, e.da);
  const auto zero = hn::Zero(df);
  const RowSpans spans(e);
  int y_lo, y_hi;
  if (!spans.rows(y_lo, y_hi)) return 0;
  // Each row's span, a batch of rows at a time (row_spans_simd-inl.h).
  BatchedRowSpans row_spans(spans, y_lo, y_hi);
  uint64_t covered = 0, writes = 0, lost = 0;
  for (int y = y_lo; y <= y_hi; ++y) {
    int x_lo, x_hi;
    if (!row_spans.at(y, x_lo, x_hi)) continue;
    const int ry = y - e.ty0;
    const auto row_depth = hn::Set(df, e.dc + e.db * float(ry));
    const int32_t start[3] = {e.e0[0] + e.dy[0] * ry, e.e0[1] + e.dy[1] * ry,
                              e.e0[2] + e.dy[2] * ry};
    const size_t row_offset = size_t(y - target.y0) * size_t(target.stride);
    const float* depth_row = target.depth + row_offset;
    const int rx_lo = x_lo - e.tx0;
    auto edge0 = hn::Add(hn::Set(di, start[0] + e.dx[0] * rx_lo), lane_step[0]);
    auto edge1 = hn::Add(hn::Set(di, start[1] + e.dx[1] * rx_lo), lane_step[1]);
    auto edge2 = hn::Add(hn::Set(di, start[2] + e.dx[2] * rx_lo), lane_step[2]);
    for (int x = x_lo; x <= x_hi; x += lanes, edge0 = hn::Add(edge0, vector_step[0]),
             edge1 = hn::Add(edge1, vector_step[1]), edge2 = hn::Add(edge2, vector_step[2])) {
      const int rx = x - e.tx0;
      // Covered: inside all three edges (>= 0); lanes past the span are off.
      auto inside_i = hn::And(hn::FirstN(di, size_t(x_hi - x + 1)), hn::Gt(edge0, minus_one));
      inside_i = hn::And(inside_i, hn::Gt(edge1, minus_one));
      inside_i = hn::And(inside_i, hn::Gt(edge2, minus_one));
      if (hn::AllFalse(di, inside_i)) continue;
      const auto inside = hn::RebindMask(df, inside_i);
      covered += hn::CountTrue(df, inside);
      // Depth rule against the stored depth, only where there is a surface (stored depth > 0).
      const auto d = hn::Add(row_depth, hn::Mul(da, hn::Iota(df, float(rx))));
      const auto stored = hn::MaskedLoad(inside, df, depth_row + (x - target.x0));
      const auto pass = rule == DepthRule::Closer ? hn::Gt(d, stored) : hn::Le(d, stored);
      const auto write = hn::And(hn::And(inside, hn::Gt(stored, zero)), pass);
      if (hn::AllFalse(df, write)) continue;
      writes += hn::CountTrue(df, write);
      const auto write_i = hn::RebindMask(di, write);
      lost += BlendPixels(di, write_i, row_offset + size_t(x - target.x0), blend, target);
    }
  }
  counts.covered += covered;
  counts.writes += writes;
  return lost;
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(MaskKernelSimd);

uint64_t maskKernel(const TileEdges& e, MaskBlend blend, DepthRule rule,
                    const MaskTarget& target, KernelCounts& counts, bool simd) {
  if (useSimd(simd)) return HWY_DYNAMIC_DISPATCH(MaskKernelSimd)(e, blend, rule, target, counts);
  return maskKernelScalar(e, blend, rule, target, counts);
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

uint64_t maskKernel(const TileEdges& e, MaskBlend blend, DepthRule rule,
                    const MaskTarget& target, KernelCounts& counts, bool) {
  return maskKernelScalar(e, blend, rule, target, counts);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
