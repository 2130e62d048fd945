// SIMD twin of sample_kernel_scalar.cpp (Highway, dispatched at run time): 4 to 16 samples per
// step, the same float operations in the same order, the side tests as all-ones lane masks.
#include "shadows/exact/sample_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/exact/sample_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SamplePositionsSimd(const float* radius2, const float* cos_phi, const float* sin_phi,
                         float one_minus_cos_max, float* x, float* y, size_t n) {
  const hn::CappedTag<float, kSampleBlock> df;
  const size_t lanes = hn::Lanes(df);
  const auto omc_max = hn::Set(df, one_minus_cos_max);
  const auto one = hn::Set(df, 1.0f), two = hn::Set(df, 2.0f);
  for (size_t i = 0; i < n; i += lanes) {
    const auto one_minus_cos = hn::Mul(hn::LoadU(df, radius2 + i), omc_max);
    const auto cos_theta = hn::Sub(one, one_minus_cos);
    const auto tan_theta =
        hn::Div(hn::Sqrt(hn::Mul(one_minus_cos, hn::Sub(two, one_minus_cos))), cos_theta);
    hn::Store(hn::Mul(tan_theta, hn::LoadU(df, cos_phi + i)), df, x + i);
    hn::Store(hn::Mul(tan_theta, hn::LoadU(df, sin_phi + i)), df, y + i);
  }
}

void AddEdgeCrossingsSimd(const SampleEdge& e, const float* x, const float* y, int32_t* count,
                          size_t n) {
  // At most kSampleBlock lanes, so that n (a multiple of it) is a whole number of vectors.
  const hn::CappedTag<float, kSampleBlock> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t lanes = hn::Lanes(df);
  const auto zero = hn::Zero(df);
  const auto a0 = hn::Set(df, e.sector_a[0]), a1 = hn::Set(df, e.sector_a[1]);
  const auto b0 = hn::Set(df, e.sector_b[0]), b1 = hn::Set(df, e.sector_b[1]);
  const auto l0 = hn::Set(df, e.line[0]), l1 = hn::Set(df, e.line[1]), l2 = hn::Set(df, e.line[2]);
  // All-ones where the wanted side is the negative one: XOR turns ">= 0" into "on that side".
  const auto flip_a = hn::Set(di, e.a_side ? 0 : -1);
  const auto flip_b = hn::Set(di, e.b_side ? 0 : -1);
  const auto flip_l = hn::Set(di, e.centre_side ? -1 : 0);  // crossed: not the centre's side
  const auto delta = hn::Set(di, e.delta);
  for (size_t i = 0; i < n; i += lanes) {
    const auto vx = hn::Load(df, x + i);
    const auto vy = hn::Load(df, y + i);
    const auto sa = hn::Add(hn::Mul(a0, vx), hn::Mul(a1, vy));
    const auto sb = hn::Add(hn::Mul(b0, vx), hn::Mul(b1, vy));
    const auto sl = hn::Add(hn::Add(hn::Mul(l0, vx), hn::Mul(l1, vy)), l2);
    const auto in_a = hn::Xor(hn::VecFromMask(di, hn::RebindMask(di, hn::Ge(sa, zero))), flip_a);
    const auto in_b = hn::Xor(hn::VecFromMask(di, hn::RebindMask(di, hn::Ge(sb, zero))), flip_b);
    const auto across =
        hn::Xor(hn::VecFromMask(di, hn::RebindMask(di, hn::Ge(sl, zero))), flip_l);
    const auto crossed = hn::And(hn::And(in_a, in_b), across);
    hn::Store(hn::Add(hn::Load(di, count + i), hn::And(crossed, delta)), di, count + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(AddEdgeCrossingsSimd);
HWY_EXPORT(SamplePositionsSimd);

void samplePositions(const float* radius2, const float* cos_phi, const float* sin_phi,
                     float one_minus_cos_max, float* x, float* y, size_t n, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(SamplePositionsSimd)(radius2, cos_phi, sin_phi, one_minus_cos_max, x, y,
                                              n);
  } else {
    samplePositionsScalar(radius2, cos_phi, sin_phi, one_minus_cos_max, x, y, n);
  }
}

void addEdgeCrossings(const SampleEdge& edge, const float* x, const float* y, int32_t* count,
                      size_t n, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(AddEdgeCrossingsSimd)(edge, x, y, count, n);
  } else {
    addEdgeCrossingsScalar(edge, x, y, count, n);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void samplePositions(const float* radius2, const float* cos_phi, const float* sin_phi,
                     float one_minus_cos_max, float* x, float* y, size_t n, bool) {
  samplePositionsScalar(radius2, cos_phi, sin_phi, one_minus_cos_max, x, y, n);
}

void addEdgeCrossings(const SampleEdge& edge, const float* x, const float* y, int32_t* count,
                      size_t n, bool) {
  addEdgeCrossingsScalar(edge, x, y, count, n);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
