// SIMD twin of occluder_kernel_scalar.cpp (Highway, dispatched at run time): 2 to 8 samples per
// step in double, the same operations in the same order, the tests as all-ones lane masks.
#include "shadows/aliasfree/occluder_test.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/aliasfree/occluder_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void MarkShadowedSamplesSimd(const OccluderTest& t, const double* dx, const double* dy,
                             const double* dz, int64_t* shadowed, size_t n) {
  // At most kOccluderBlock lanes, so that n (a multiple of it) is a whole number of vectors.
  const hn::CappedTag<double, kOccluderBlock> dd;
  const hn::RebindToSigned<decltype(dd)> di;
  const size_t lanes = hn::Lanes(dd);
  const auto zero = hn::Zero(dd);
  const auto e00 = hn::Set(dd, t.edge[0][0]), e01 = hn::Set(dd, t.edge[0][1]),
             e02 = hn::Set(dd, t.edge[0][2]);
  const auto e10 = hn::Set(dd, t.edge[1][0]), e11 = hn::Set(dd, t.edge[1][1]),
             e12 = hn::Set(dd, t.edge[1][2]);
  const auto e20 = hn::Set(dd, t.edge[2][0]), e21 = hn::Set(dd, t.edge[2][1]),
             e22 = hn::Set(dd, t.edge[2][2]);
  const auto p0 = hn::Set(dd, t.plane[0]), p1 = hn::Set(dd, t.plane[1]),
             p2 = hn::Set(dd, t.plane[2]), offset = hn::Set(dd, t.offset);
  // All-ones where an edge owns its ties: a value of 0 then counts as inside.
  const auto tie0 = hn::Set(di, t.edge_ties[0] ? -1 : 0);
  const auto tie1 = hn::Set(di, t.edge_ties[1] ? -1 : 0);
  const auto tie2 = hn::Set(di, t.edge_ties[2] ? -1 : 0);
  const auto inside = [&](auto v, auto tie) {
    const auto gt = hn::VecFromMask(di, hn::RebindMask(di, hn::Gt(v, zero)));
    const auto eq = hn::VecFromMask(di, hn::RebindMask(di, hn::Eq(v, zero)));
    return hn::Or(gt, hn::And(tie, eq));
  };
  for (size_t i = 0; i < n; i += lanes) {
    const auto x = hn::Load(dd, dx + i);
    const auto y = hn::Load(dd, dy + i);
    const auto z = hn::Load(dd, dz + i);
    const auto v0 = hn::Add(hn::Add(hn::Mul(e00, x), hn::Mul(e01, y)), hn::Mul(e02, z));
    const auto v1 = hn::Add(hn::Add(hn::Mul(e10, x), hn::Mul(e11, y)), hn::Mul(e12, z));
    const auto v2 = hn::Add(hn::Add(hn::Mul(e20, x), hn::Mul(e21, y)), hn::Mul(e22, z));
    const auto behind =
        hn::Sub(hn::Add(hn::Add(hn::Mul(p0, x), hn::Mul(p1, y)), hn::Mul(p2, z)), offset);
    const auto beyond = hn::VecFromMask(di, hn::RebindMask(di, hn::Gt(behind, zero)));
    const auto hit =
        hn::And(hn::And(inside(v0, tie0), inside(v1, tie1)), hn::And(inside(v2, tie2), beyond));
    hn::Store(hn::Or(hn::Load(di, shadowed + i), hit), di, shadowed + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(MarkShadowedSamplesSimd);

void markShadowedSamples(const OccluderTest& test, const double* dx, const double* dy,
                         const double* dz, int64_t* shadowed, size_t n, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(MarkShadowedSamplesSimd)(test, dx, dy, dz, shadowed, n);
  } else {
    markShadowedSamplesScalar(test, dx, dy, dz, shadowed, n);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void markShadowedSamples(const OccluderTest& test, const double* dx, const double* dy,
                         const double* dz, int64_t* shadowed, size_t n, bool) {
  markShadowedSamplesScalar(test, dx, dy, dz, shadowed, n);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
