// Per-target helpers of the shadow-map lookup kernels (map_lookup_kernel_simd.cpp,
// pcss_kernel_simd.cpp): a lane's texel read, as occluderAt in map_lookup_kernel.h. Included
// once per Highway target (the include guard toggles with HWY_TARGET_TOGGLE).
#if defined(PENUMBRA_MAP_LOOKUP_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef PENUMBRA_MAP_LOOKUP_SIMD_INL_H_
#undef PENUMBRA_MAP_LOOKUP_SIMD_INL_H_
#else
#define PENUMBRA_MAP_LOOKUP_SIMD_INL_H_
#endif

#include <cmath>

#include <hwy/highway.h>

#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// int(floor(v)) per lane; v is in int range (clampLookupPosition).
template <class DD>
HWY_INLINE hn::Vec<hn::Rebind<int32_t, DD>> FloorToInt(DD dd, hn::Vec<DD> v) {
  (void)dd;
  return hn::DemoteTo(hn::Rebind<int32_t, DD>(), hn::Floor(v));
}

// occluderAt(face, i, j) per lane: the texel clamped to the face, gathered as float, read back
// as near / double(stored), +infinity where nothing was drawn.
template <class DD>
HWY_INLINE hn::Vec<DD> OccluderAt(DD dd, const FaceTexels& face,
                                  hn::Vec<hn::Rebind<int32_t, DD>> i,
                                  hn::Vec<hn::Rebind<int32_t, DD>> j) {
  const hn::Rebind<int32_t, DD> di;
  const hn::Rebind<float, DD> df;
  const auto zero = hn::Zero(di), last = hn::Set(di, face.size - 1);
  const auto ci = hn::Min(hn::Max(i, zero), last), cj = hn::Min(hn::Max(j, zero), last);
  const auto index = hn::Add(hn::Mul(cj, hn::Set(di, face.size)), ci);
  const auto stored = hn::PromoteTo(dd, hn::GatherIndex(df, face.texels, index));
  return hn::IfThenElse(hn::Eq(stored, hn::Zero(dd)), hn::Set(dd, double(INFINITY)),
                        hn::Div(hn::Set(dd, face.near), stored));
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#endif  // include guard
