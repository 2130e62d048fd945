// SIMD twin of map_lookup_kernel_scalar.cpp (Highway, dispatched at run time): one point per
// double lane (2 to 8 of them), the kernel's taps gathered from the face, the same double
// operations in the same order.
#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/stages/light_depth_maps/map_lookup_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

#include "shadows/stages/light_depth_maps/map_lookup_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void PcfVisibilitySimd(const FaceTexels& face, const double* sx, const double* sy,
                       const double* receiver, const double* ring_bias, int kernel,
                       float* visibility, size_t n) {
  // At most kLookupBlock lanes, so that n (a multiple of it) is a whole number of vectors.
  const hn::CappedTag<double, kLookupBlock> dd;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t lanes = hn::Lanes(dd);
  const auto half = hn::Set(dd, 0.5 * (kernel - 1));
  const auto one = hn::Set(dd, 1.0);
  const float taps = float(kernel * kernel);
  HWY_ALIGN double lit_lanes[kLookupBlock];
  for (size_t p = 0; p < n; p += lanes) {
    const auto x0 = FloorToInt(dd, hn::Sub(hn::LoadU(dd, sx + p), half));
    const auto y0 = FloorToInt(dd, hn::Sub(hn::LoadU(dd, sy + p), half));
    const auto recv = hn::LoadU(dd, receiver + p);
    const auto step = hn::LoadU(dd, ring_bias + p);
    const int half_taps = (kernel - 1) / 2;
    auto lit = hn::Zero(dd);  // whole numbers, exact in double
    for (int j = 0; j < kernel; ++j) {
      const auto yj = hn::Add(y0, hn::Set(di, j));
      for (int i = 0; i < kernel; ++i) {
        const int ring = std::max(std::abs(i - half_taps), std::abs(j - half_taps));
        const auto tap_receiver = hn::Sub(recv, hn::Mul(hn::Set(dd, double(ring)), step));
        const auto d = OccluderAt(dd, face, hn::Add(x0, hn::Set(di, i)), yj);
        lit = hn::Add(lit, hn::IfThenElseZero(hn::Ge(d, tap_receiver), one));
      }
    }
    hn::Store(lit, dd, lit_lanes);
    for (size_t l = 0; l < lanes; ++l) visibility[p + l] = float(int(lit_lanes[l])) / taps;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(PcfVisibilitySimd);

void pcfVisibility(const FaceTexels& face, const double* sx, const double* sy,
                   const double* receiver, const double* ring_bias, int kernel, float* visibility,
                   size_t n, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(PcfVisibilitySimd)(face, sx, sy, receiver, ring_bias, kernel,
                                            visibility, n);
  } else {
    pcfVisibilityScalar(face, sx, sy, receiver, ring_bias, kernel, visibility, n);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void pcfVisibility(const FaceTexels& face, const double* sx, const double* sy,
                   const double* receiver, const double* ring_bias, int kernel, float* visibility,
                   size_t n, bool) {
  pcfVisibilityScalar(face, sx, sy, receiver, ring_bias, kernel, visibility, n);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
