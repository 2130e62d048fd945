// SIMD twin of square_coverage_kernel_scalar.cpp (Highway, dispatched at run time): one pair per
// lane, the same float operations in the same order; the scalar twin's early returns and
// branches become lane masks. Lanes past the last whole vector take the scalar twin.
#include "shadows/coverage/square_coverage_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/coverage/square_coverage_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// sideArea of the scalar twin.
template <class D, class V>
HWY_INLINE V SideArea(D df, V ax, V ay, V bx, V by) {
  const V zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto ax_zero = hn::Eq(ax, zero), bx_zero = hn::Eq(bx, zero);
  const V ra = hn::Div(ay, hn::IfThenElse(ax_zero, one, ax));
  const V rb = hn::Div(by, hn::IfThenElse(bx_zero, one, bx));
  V lo = hn::Neg(one), hi = one;
  lo = hn::IfThenElse(hn::Gt(ax, zero), hn::IfThenElse(hn::Gt(ra, lo), ra, lo), lo);
  hi = hn::IfThenElse(hn::Lt(ax, zero), hn::IfThenElse(hn::Lt(ra, hi), ra, hi), hi);
  hi = hn::IfThenElse(hn::Gt(bx, zero), hn::IfThenElse(hn::Lt(rb, hi), rb, hi), hi);
  lo = hn::IfThenElse(hn::Lt(bx, zero), hn::IfThenElse(hn::Gt(rb, lo), rb, lo), lo);
  const auto open = hn::And(hn::Or(hn::Not(ax_zero), hn::Le(ay, zero)),
                            hn::Or(hn::Not(bx_zero), hn::Ge(by, zero)));
  const V width = hn::Sub(hi, lo);
  return hn::IfThenElseZero(hn::And(open, hn::Gt(width, zero)), hn::Mul(width, hn::Set(df, 0.5f)));
}

// One slab of the scalar twin: clips [lo, hi] to |m + s u| <= 1 along one axis; where u is 0,
// the lane stays valid only if |m| <= 1.
template <class D, class V, class M>
HWY_INLINE void Slab(D df, V m, V u, V& lo, V& hi, M& valid) {
  const V zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto u_zero = hn::Eq(u, zero);
  const V divisor = hn::IfThenElse(u_zero, one, u);
  const V c0 = hn::Div(hn::Sub(hn::Neg(one), m), divisor);
  const V c1 = hn::Div(hn::Sub(one, m), divisor);
  const auto order = hn::Lt(c0, c1);
  const V near = hn::IfThenElse(order, c0, c1), far = hn::IfThenElse(order, c1, c0);
  lo = hn::IfThenElse(u_zero, lo, hn::IfThenElse(hn::Gt(near, lo), near, lo));
  hi = hn::IfThenElse(u_zero, hi, hn::IfThenElse(hn::Lt(far, hi), far, hi));
  valid = hn::And(valid, hn::Or(hn::Not(u_zero), hn::Le(hn::Abs(m), one)));
}

void SquareCoverageSimd(const DiskCoverageBatch& b, size_t n, size_t* done) {
  const hn::ScalableTag<float> df;
  const size_t lanes = hn::Lanes(df);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto min_depth = hn::Set(df, kMinDepth);
  const auto half = hn::Set(df, 0.5f), quarter = hn::Set(df, 0.25f);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes) {
    const auto x0 = hn::LoadU(df, b.x0 + i), y0 = hn::LoadU(df, b.y0 + i);
    const auto w0 = hn::LoadU(df, b.w0 + i), x1 = hn::LoadU(df, b.x1 + i);
    const auto y1 = hn::LoadU(df, b.y1 + i), w1 = hn::LoadU(df, b.w1 + i);
    const auto keep0 = hn::Ge(w0, min_depth), keep1 = hn::Ge(w1, min_depth);
    auto valid = hn::Or(keep0, keep1);
    const auto dw = hn::Sub(w1, w0);
    const auto both = hn::And(keep0, keep1);
    const auto tc = hn::Div(hn::Sub(min_depth, w0), hn::IfThenElse(both, one, dw));
    const auto t0 = hn::IfThenElse(keep0, zero, tc);
    const auto t1 = hn::IfThenElse(keep1, one, tc);
    const auto dx = hn::Sub(x1, x0), dy = hn::Sub(y1, y0);
    const auto ax = hn::Add(x0, hn::Mul(t0, dx)), ay = hn::Add(y0, hn::Mul(t0, dy));
    const auto aw = hn::IfThenElse(keep0, w0, min_depth);
    const auto bx = hn::Add(x0, hn::Mul(t1, dx)), by = hn::Add(y0, hn::Mul(t1, dy));
    const auto bw = hn::IfThenElse(keep1, w1, min_depth);
    const auto l1 = hn::Sub(hn::Mul(ay, bw), hn::Mul(aw, by));
    const auto l2 = hn::Sub(hn::Mul(aw, bx), hn::Mul(ax, bw));
    const auto l3 = hn::Sub(hn::Mul(ax, by), hn::Mul(ay, bx));
    const auto n2 = hn::Add(hn::Mul(l1, l1), hn::Mul(l2, l2));
    const auto n2_positive = hn::Gt(n2, zero);
    valid = hn::And(valid, hn::And(n2_positive, hn::Ne(l3, zero)));
    const auto inv_n = hn::Div(one, hn::Sqrt(hn::IfThenElse(n2_positive, n2, one)));
    const auto ux = hn::Mul(l2, inv_n), uy = hn::Mul(hn::Neg(l1), inv_n);
    const auto dist = hn::Mul(l3, inv_n);
    const auto mx = hn::Neg(hn::Mul(dist, hn::Mul(l1, inv_n)));
    const auto my = hn::Neg(hn::Mul(dist, hn::Mul(l2, inv_n)));
    auto lo = hn::Div(hn::Add(hn::Mul(ax, ux), hn::Mul(ay, uy)), aw);
    auto hi = hn::Div(hn::Add(hn::Mul(bx, ux), hn::Mul(by, uy)), bw);
    Slab(df, mx, ux, lo, hi, valid);
    Slab(df, my, uy, lo, hi, valid);
    valid = hn::And(valid, hn::Gt(hi, lo));
    const auto q0x = hn::Add(mx, hn::Mul(lo, ux)), q0y = hn::Add(my, hn::Mul(lo, uy));
    const auto q1x = hn::Add(mx, hn::Mul(hi, ux)), q1y = hn::Add(my, hn::Mul(hi, uy));
    const auto ccw = hn::Gt(l3, zero);
    auto pax = hn::IfThenElse(ccw, q0x, q1x), pay = hn::IfThenElse(ccw, q0y, q1y);
    auto pbx = hn::IfThenElse(ccw, q1x, q0x), pby = hn::IfThenElse(ccw, q1y, q0y);
    const auto triangle = hn::Mul(hn::Sub(hn::Mul(pax, pby), hn::Mul(pay, pbx)), half);
    auto cone = zero;
    for (int side = 0; side < 4; ++side) {
      cone = hn::Add(cone, SideArea(df, pax, pay, pbx, pby));
      const auto tax = pay, tay = hn::Neg(pax), tbx = pby, tby = hn::Neg(pbx);
      pax = tax, pay = tay, pbx = tbx, pby = tby;
    }
    const auto fraction = hn::Mul(hn::Sub(cone, triangle), quarter);
    const auto signed_fraction = hn::IfThenElse(ccw, fraction, hn::Neg(fraction));
    hn::StoreU(hn::IfThenElseZero(valid, signed_fraction), df, b.fraction + i);
  }
  *done = i;
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(SquareCoverageSimd);

void squareCoverage(const DiskCoverageBatch& batch, size_t n, bool simd) {
  size_t done = 0;
  if (useSimd(simd)) HWY_DYNAMIC_DISPATCH(SquareCoverageSimd)(batch, n, &done);
  for (size_t i = done; i < n; ++i) {
    batch.fraction[i] = squareCoverageOne(batch.x0[i], batch.y0[i], batch.w0[i], batch.x1[i],
                                          batch.y1[i], batch.w1[i]);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void squareCoverage(const DiskCoverageBatch& batch, size_t n, bool) {
  squareCoverageScalar(batch, n);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
