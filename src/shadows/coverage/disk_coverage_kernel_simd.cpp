// SIMD twin of disk_coverage_kernel_scalar.cpp (Highway, dispatched at run time): one pair per
// lane, the same float operations in the same order; the scalar twin's early returns become
// lane masks applied at the end, and its divisions that a returned lane skips are made with a
// harmless divisor. Lanes past the last whole vector take the scalar twin.
#include "shadows/coverage/disk_coverage_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/coverage/disk_coverage_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D, class V>
HWY_INLINE V AtanUnit(D d, V x) {
  const V x2 = hn::Mul(x, x);
  V p = hn::Set(d, -0.0117212f);
  p = hn::Add(hn::Mul(p, x2), hn::Set(d, 0.05265332f));
  p = hn::Add(hn::Mul(p, x2), hn::Set(d, -0.11643287f));
  p = hn::Add(hn::Mul(p, x2), hn::Set(d, 0.19354346f));
  p = hn::Add(hn::Mul(p, x2), hn::Set(d, -0.33262347f));
  p = hn::Add(hn::Mul(p, x2), hn::Set(d, 0.99997726f));
  return hn::Mul(p, x);
}

// angleOf of the scalar twin: atan2(s, d) for d >= 0.
template <class D, class V>
HWY_INLINE V AngleOf(D df, V s, V d) {
  const V zero = hn::Zero(df);
  const V a = hn::Abs(s);
  const auto a_big = hn::Gt(a, d);
  const V big = hn::IfThenElse(a_big, a, d);
  const V small = hn::IfThenElse(a_big, d, a);
  const auto big_positive = hn::Gt(big, zero);
  const V ratio = hn::IfThenElseZero(
      big_positive, hn::Div(small, hn::IfThenElse(big_positive, big, hn::Set(df, 1.0f))));
  const V t = AtanUnit(df, ratio);
  const V r = hn::IfThenElse(a_big, hn::Sub(hn::Set(df, 1.57079632679489662f), t), t);
  return hn::IfThenElse(hn::Lt(s, zero), hn::Neg(r), r);
}

void DiskCoverageSimd(const DiskCoverageBatch& b, size_t n, size_t* done) {
  const hn::ScalableTag<float> df;
  const size_t lanes = hn::Lanes(df);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto min_depth = hn::Set(df, kMinDepth);
  const auto half = hn::Set(df, 0.5f), inv_pi = hn::Set(df, 0.318309886183790672f);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes) {
    const auto x0 = hn::LoadU(df, b.x0 + i), y0 = hn::LoadU(df, b.y0 + i);
    const auto w0 = hn::LoadU(df, b.w0 + i), x1 = hn::LoadU(df, b.x1 + i);
    const auto y1 = hn::LoadU(df, b.y1 + i), w1 = hn::LoadU(df, b.w1 + i);
    const auto keep0 = hn::Ge(w0, min_depth), keep1 = hn::Ge(w1, min_depth);
    auto valid = hn::Or(keep0, keep1);
    const auto dw = hn::Sub(w1, w0);
    const auto both = hn::And(keep0, keep1);
    // A lane that keeps neither end divides by dw, which may be 0; it is masked out below.
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
    valid = hn::And(valid, n2_positive);
    const auto inv_n = hn::Div(one, hn::Sqrt(hn::IfThenElse(n2_positive, n2, one)));
    const auto d = hn::Mul(hn::Abs(l3), inv_n);
    const auto h2 = hn::Sub(one, hn::Mul(d, d));
    const auto h2_positive = hn::Gt(h2, zero);
    valid = hn::And(valid, h2_positive);
    const auto h = hn::Sqrt(hn::IfThenElse(h2_positive, h2, one));
    const auto ux = hn::Mul(l2, inv_n), uy = hn::Mul(hn::Neg(l1), inv_n);
    const auto sa = hn::Div(hn::Add(hn::Mul(ax, ux), hn::Mul(ay, uy)), aw);
    const auto sb = hn::Div(hn::Add(hn::Mul(bx, ux), hn::Mul(by, uy)), bw);
    const auto neg_h = hn::Neg(h);
    const auto lo = hn::IfThenElse(hn::Gt(sa, neg_h), sa, neg_h);
    const auto hi = hn::IfThenElse(hn::Lt(sb, h), sb, h);
    valid = hn::And(valid, hn::Gt(hi, lo));
    const auto angle = hn::Sub(AngleOf(df, hi, d), AngleOf(df, lo, d));
    const auto area = hn::Mul(hn::Sub(angle, hn::Mul(hn::Sub(hi, lo), d)), half);
    const auto fraction = hn::Mul(area, inv_pi);
    const auto signed_fraction = hn::IfThenElse(hn::Lt(l3, zero), hn::Neg(fraction), fraction);
    hn::StoreU(hn::IfThenElseZero(valid, signed_fraction), df, b.fraction + i);
  }
  *done = i;
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(DiskCoverageSimd);

void diskCoverage(const DiskCoverageBatch& batch, size_t n, bool simd) {
  size_t done = 0;
  if (useSimd(simd)) HWY_DYNAMIC_DISPATCH(DiskCoverageSimd)(batch, n, &done);
  for (size_t i = done; i < n; ++i) {
    batch.fraction[i] = diskCoverageOne(batch.x0[i], batch.y0[i], batch.w0[i], batch.x1[i],
                                        batch.y1[i], batch.w1[i]);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void diskCoverage(const DiskCoverageBatch& batch, size_t n, bool) {
  diskCoverageScalar(batch, n);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
