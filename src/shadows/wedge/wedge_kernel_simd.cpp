// SIMD twin of wedge_kernel_scalar.cpp (Highway, dispatched at run time): the triangle
// coverage, the umbra depth test, the four plane evaluations and equation (3) run 4 to 16
// pixels at a time with the same float operations in the same order; the few pixels that
// receive a contribution are then added to the 16-bit LI buffer one by one, as in the twin.
#include <algorithm>

#include "core/simd_dispatch.h"
#include "shadows/wedge/wedge_kernel.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/wedge/wedge_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

#include "raster/row_spans_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class DF>
HWY_INLINE hn::Vec<DF> planeAt(DF df, const ScreenPlane& p, hn::Vec<DF> sx, hn::Vec<DF> sy,
                               hn::Vec<DF> z) {
  // ((a sx + b sy) + c z) + d, as ScreenPlane::eval.
  const auto ab = hn::Add(hn::Mul(hn::Set(df, p.a), sx), hn::Mul(hn::Set(df, p.b), sy));
  return hn::Add(hn::Add(ab, hn::Mul(hn::Set(df, p.c), z)), hn::Set(df, p.d));
}

// The light intensity s in [0, 1] from the four plane values (2002 paper, section 4.2:
// screenIntensity, wedge_screen.h), operation for operation, smoothed where the wedge asks.
template <class DF>
HWY_INLINE hn::Vec<DF> screenIntensityLanes(DF df, const ScreenWedge& w, hn::Vec<DF> f,
                                            hn::Vec<DF> b, hn::Vec<DF> l, hn::Vec<DF> r) {
  const auto zero = hn::Zero(df);
  const auto one = hn::Set(df, 1.0f);
  const ScreenIntensity& k = w.k;
  const auto dl =
      hn::Add(hn::Mul(f, hn::Set(df, k.back_left)), hn::Mul(b, hn::Set(df, k.front_left)));
  const auto dr =
      hn::Add(hn::Mul(f, hn::Set(df, k.back_right)), hn::Mul(b, hn::Set(df, k.front_right)));
  const auto rl = hn::Mul(r, hn::Set(df, k.left));
  const auto lr = hn::Mul(l, hn::Set(df, k.right));
  const auto numerator = hn::Mul(
      b, hn::Add(hn::Mul(hn::Mul(rl, hn::Set(df, k.front_left)), dr),
                 hn::Mul(hn::Mul(lr, hn::Set(df, k.front_right)), dl)));
  const auto denominator = hn::Mul(hn::Mul(hn::Add(rl, lr), dl), dr);
  const auto positive = hn::Gt(denominator, zero);
  // Divide only where the denominator is positive (no 0/0 lanes), else 0.5.
  const auto safe_denominator = hn::IfThenElse(positive, denominator, one);
  auto s = hn::IfThenElse(positive, hn::Div(numerator, safe_denominator), hn::Set(df, 0.5f));
  s = hn::IfThenElse(hn::Lt(s, zero), zero, s);
  s = hn::IfThenElse(hn::Gt(s, one), one, s);
  if (w.smooth) {  // smoothFalloff: (3 s) s - ((2 s) s) s
    s = hn::Sub(hn::Mul(hn::Mul(hn::Set(df, 3.0f), s), s),
                hn::Mul(hn::Mul(hn::Mul(hn::Set(df, 2.0f), s), s), s));
  }
  return s;
}

// The penumbra part (2002 paper, section 4.2): where the depth-buffer point (sx, sy, stored)
// lies inside all four wedge planes, round(li_scale s) is added to `value` and the lane to
// `write`; the pixels inside are counted.
template <class DF, class DI>
HWY_INLINE void addPenumbra(DF df, DI di, const ScreenWedge& w, float li_scale, hn::Vec<DF> sx,
                            hn::Vec<DF> sy, hn::Vec<DF> stored, hn::Mask<DF> surface,
                            hn::Vec<DI>& value, hn::Mask<DF>& write, uint64_t& inside) {
  const auto zero = hn::Zero(df);
  const auto f = planeAt(df, w.front, sx, sy, stored);
  const auto b = planeAt(df, w.back, sx, sy, stored);
  const auto l = planeAt(df, w.left, sx, sy, stored);
  const auto r = planeAt(df, w.right, sx, sy, stored);
  auto in = hn::And(surface, hn::Ge(f, zero));
  in = hn::And(in, hn::Ge(b, zero));
  in = hn::And(in, hn::Ge(l, zero));
  in = hn::And(in, hn::Ge(r, zero));
  if (hn::AllFalse(df, in)) return;
  inside += hn::CountTrue(df, in);
  const auto s = screenIntensityLanes(df, w, f, b, l, r);
  // round(li_scale s): to nearest, ties to even.
  const auto penumbra = hn::NearestInt(hn::Mul(s, hn::Set(df, li_scale)));
  value = hn::Add(value, hn::IfThenElseZero(hn::RebindMask(di, in), penumbra));
  write = hn::Or(write, in);
}

// Adds each lane's value in `write` to the 16-bit LI buffer (liAdd, wrapping), pixel by pixel
// (the few that receive a contribution); `n` lanes lie in the span.
template <class DI, class M>
HWY_INLINE void addToLiRow(DI di, hn::Vec<DI> value, M write, int n, int16_t* li,
                           uint64_t& writes) {
  constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);  // 16 with AVX-512
  HWY_ALIGN int32_t values[kMaxLanes];
  HWY_ALIGN int32_t written[kMaxLanes];
  hn::Store(value, di, values);
  hn::Store(hn::VecFromMask(di, hn::RebindMask(di, write)), di, written);
  for (int i = 0; i < n; ++i) {
    if (written[i] == 0) continue;
    li[i] = liAdd(li[i], values[i]);
    ++writes;
  }
}

void WedgeKernelSimd(const TileEdges& e, const WedgeKernelWork& work,
                     const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
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
  const auto zero = hn::Zero(df);
  const auto half = hn::Set(df, 0.5f);
  const auto da = hn::Set(df, e.da);
  const ScreenWedge* w = work.wedge;
  const RowSpans spans(e);
  int y_lo, y_hi;
  if (!spans.rows(y_lo, y_hi)) return;
  // Each row's span, a batch of rows at a time (row_spans_simd-inl.h).
  BatchedRowSpans row_spans(spans, y_lo, y_hi);
  WedgeKernelCounts local;  // in registers: through `counts` each update would go to memory
  for (int y = y_lo; y <= y_hi; ++y) {
    int x_lo, x_hi;
    if (!row_spans.at(y, x_lo, x_hi)) continue;
    const int ry = y - e.ty0;
    const auto row_depth = hn::Set(df, e.dc + e.db * float(ry));
    const auto sy = hn::Set(df, float(y) + 0.5f);
    const int32_t r0 = e.e0[0] + e.dy[0] * ry, r1 = e.e0[1] + e.dy[1] * ry,
                  r2 = e.e0[2] + e.dy[2] * ry;
    const float* depth_row = target.depth + target.index(target.x0, y);
    int16_t* li_row = target.li + target.index(target.x0, y);
    // The row's edge values, stepped by dx * lanes from one vector to the next.
    const int rx_lo = x_lo - e.tx0;
    auto edge0 = hn::Add(hn::Set(di, r0 + e.dx[0] * rx_lo), lane_step[0]);
    auto edge1 = hn::Add(hn::Set(di, r1 + e.dx[1] * rx_lo), lane_step[1]);
    auto edge2 = hn::Add(hn::Set(di, r2 + e.dx[2] * rx_lo), lane_step[2]);
    for (int x = x_lo; x <= x_hi; x += lanes, edge0 = hn::Add(edge0, vector_step[0]),
             edge1 = hn::Add(edge1, vector_step[1]), edge2 = hn::Add(edge2, vector_step[2])) {
      const int rx = x - e.tx0;
      // Covered: inside all three edges (>= 0); lanes past the span are off.
      auto inside_i = hn::FirstN(di, size_t(x_hi - x + 1));
      inside_i = hn::And(inside_i, hn::Gt(edge0, minus_one));
      inside_i = hn::And(inside_i, hn::Gt(edge1, minus_one));
      inside_i = hn::And(inside_i, hn::Gt(edge2, minus_one));
      if (hn::AllFalse(di, inside_i)) continue;
      const auto covered = hn::RebindMask(df, inside_i);
      local.covered += hn::CountTrue(df, covered);
      const auto stored = hn::MaskedLoad(covered, df, depth_row + (x - target.x0));
      // background: nothing to shadow
      const auto surface = hn::And(covered, hn::Gt(stored, zero));
      if (hn::AllFalse(df, surface)) continue;
      auto value = hn::Zero(di);
      auto write = hn::And(surface, hn::Lt(stored, zero));  // all false, of the right type
      // Umbra part: add umbra_value where the triangle's depth passes `rule`.
      if (work.umbra_value != 0) {
        const auto d = hn::Add(row_depth, hn::Mul(da, hn::Iota(df, float(rx))));
        const auto pass = work.rule == DepthRule::Closer ? hn::Gt(d, stored) : hn::Le(d, stored);
        const auto umbra = hn::And(surface, pass);
        value = hn::IfThenElseZero(hn::RebindMask(di, umbra), hn::Set(di, work.umbra_value));
        write = umbra;
      }
      // Penumbra part: is the depth-buffer point inside all four wedge planes?
      if (w != nullptr) {
        const auto sx = hn::Add(hn::Iota(df, float(x)), half);
        addPenumbra(df, di, *w, work.li_scale, sx, sy, stored, surface, value, write,
                    local.inside);
      }
      // Add to the 16-bit LI buffer (liAdd, wrapping), pixel by pixel.
      if (hn::AllFalse(df, write)) continue;
      addToLiRow(di, value, write, std::min(lanes, x_hi - x + 1), li_row + (x - target.x0),
                 local.writes);
    }
  }
  counts.covered += local.covered;
  counts.writes += local.writes;
  counts.inside += local.inside;
}


}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(WedgeKernelSimd);

void wedgeKernel(const TileEdges& e, const WedgeKernelWork& work, const WedgeKernelTarget& target,
                 WedgeKernelCounts& counts, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(WedgeKernelSimd)(e, work, target, counts);
  } else {
    wedgeKernelScalar(e, work, target, counts);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void wedgeKernel(const TileEdges& e, const WedgeKernelWork& work, const WedgeKernelTarget& target,
                 WedgeKernelCounts& counts, bool) {
  wedgeKernelScalar(e, work, target, counts);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
