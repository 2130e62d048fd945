// SIMD twin of pcss_kernel_scalar.cpp (Highway, dispatched at run time): one point per double
// lane (2 to 8 of them), each lane with its own search and filter widths, the samples' texels
// gathered from the face, the same double operations in the same order. A vector whose points
// all end early (nothing in front, no blocker found) skips the step they do not need.
#include "shadows/pcss/pcss_kernel.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/pcss/pcss_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

#include "shadows/stages/light_depth_maps/map_lookup_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void PcssVisibilitySimd(const PcssFace& face, const PcssShape& shape, const PcssPoints& pts,
                        float* visibility, size_t n, uint64_t& reads) {
  // At most kLookupBlock lanes, so that n (a multiple of it) is a whole number of vectors.
  const hn::CappedTag<double, kLookupBlock> dd;
  using V = hn::Vec<decltype(dd)>;
  const size_t lanes = hn::Lanes(dd);
  const auto zero = hn::Zero(dd), one = hn::Set(dd, 1.0), half = hn::Set(dd, 0.5);
  const auto size = hn::Set(dd, double(face.texels.size));
  const auto nearest = hn::Set(dd, face.nearest);
  const auto light_radius = hn::Set(dd, shape.light_radius);
  const auto per_tangent = hn::Set(dd, face.texels_per_tangent);
  const auto constant_bias = hn::Set(dd, shape.constant_bias);
  const auto blocker_n = hn::Set(dd, double(shape.blocker->n));
  HWY_ALIGN double found_lanes[kLookupBlock], search_lanes[kLookupBlock], lit_lanes[kLookupBlock];
  for (size_t p = 0; p < n; p += lanes) {
    const V w = hn::LoadU(dd, pts.w + p);
    const auto in_front = hn::Lt(nearest, w);
    if (hn::AllFalse(dd, in_front)) {
      for (size_t l = 0; l < lanes; ++l) visibility[p + l] = 1.0f;
      continue;
    }
    const V sx = hn::LoadU(dd, pts.sx + p), sy = hn::LoadU(dd, pts.sy + p);
    const V texel = hn::LoadU(dd, pts.texel + p), slope_bias = hn::LoadU(dd, pts.slope_bias + p);
    const V tc = hn::LoadU(dd, pts.turn_cos + p), ts = hn::LoadU(dd, pts.turn_sin + p);
    const auto receiverAt = [&](V offset) {
      return hn::Sub(w, hn::Mul(texel, hn::Add(constant_bias,
                                               hn::Mul(slope_bias, hn::Add(offset, half)))));
    };
    const auto diskTexelsV = [&](V d) {
      return hn::Mul(hn::Div(hn::Mul(light_radius, hn::Sub(w, d)), hn::Mul(d, w)), per_tangent);
    };
    // The plane's arrays are read only for the plane test (the depth test may pass none).
    const bool plane = shape.plane_test;
    const V a = plane ? hn::LoadU(dd, pts.plane_a + p) : zero;
    const V step_x = plane ? hn::LoadU(dd, pts.plane_x + p) : zero;
    const V step_y = plane ? hn::LoadU(dd, pts.plane_y + p) : zero;
    const V step = hn::Div(hn::Neg(a), w), least = hn::Mul(texel, constant_bias);
    // The scalar twin's occludes(d, offset, dx, dy); padded lanes (w = 0) get NaN steps, and
    // d = +infinity fails d < w, as the scalar twin's short cut does.
    const auto occludes = [&](V d, V offset, V dx, V dy) {
      if (!shape.plane_test) return hn::Lt(d, receiverAt(offset));
      const V slope = hn::Add(hn::Add(step, hn::Mul(step_x, dx)), hn::Mul(step_y, dy));
      return hn::And(hn::Lt(d, w), hn::Gt(hn::Add(a, hn::Mul(d, slope)), least));
    };
    const auto forSpiral = [&](const VogelSpiral& spiral, V width, auto&& fn) {
      for (int k = 0; k < spiral.n; ++k) {
        const V r = hn::Mul(width, hn::Set(dd, spiral.radius[size_t(k)]));
        const V ck = hn::Set(dd, spiral.cos[size_t(k)]), sk = hn::Set(dd, spiral.sin[size_t(k)]);
        const V c = hn::Sub(hn::Mul(ck, tc), hn::Mul(sk, ts));
        const V s = hn::Add(hn::Mul(sk, tc), hn::Mul(ck, ts));
        const V tx = hn::Floor(hn::Add(sx, hn::Mul(r, c)));
        const V ty = hn::Floor(hn::Add(sy, hn::Mul(r, s)));
        fn(OccluderAt(dd, face.texels, FloorToInt(dd, tx), FloorToInt(dd, ty)), r,
           hn::Sub(hn::Add(tx, half), sx), hn::Sub(hn::Add(ty, half), sy));
      }
    };
    // 1. Blocker search; lanes with nothing in front search a zero-width disk, ignored after.
    const V search = hn::IfThenElseZero(in_front, hn::Min(diskTexelsV(nearest), size));
    V blockers = zero, found = zero;
    forSpiral(*shape.blocker, search, [&](V d, V offset, V dx, V dy) {
      const auto hit = occludes(d, offset, dx, dy);
      blockers = hn::Add(blockers, hn::IfThenElseZero(hit, d));
      found = hn::Add(found, hn::IfThenElseZero(hit, one));
    });
    // 2. and 3. where some lane goes on: a blocker found, and not all of them at a point light.
    const auto filtered = hn::AndNot(
        hn::Or(hn::Eq(found, zero), hn::And(hn::Eq(found, blocker_n), hn::Eq(search, zero))),
        in_front);
    V lit = zero;
    if (!hn::AllFalse(dd, filtered)) {
      // Lanes that stop here filter over a zero-width disk (their average would be 0 / 0).
      const V average = hn::IfThenElse(filtered, hn::Div(blockers, found), w);
      const V width = hn::IfThenElseZero(filtered, hn::Min(diskTexelsV(average), size));
      forSpiral(*shape.filter, width, [&](V d, V offset, V dx, V dy) {
        lit = hn::Add(lit, hn::IfThenElseZero(hn::Not(occludes(d, offset, dx, dy)), one));
      });
    }
    hn::Store(found, dd, found_lanes);
    hn::Store(search, dd, search_lanes);
    hn::Store(lit, dd, lit_lanes);
    for (size_t l = 0; l < lanes; ++l)
      visibility[p + l] = pcssFinish(face, shape, pts.w[p + l], found_lanes[l], search_lanes[l],
                                     lit_lanes[l], reads);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(PcssVisibilitySimd);

void pcssVisibility(const PcssFace& face, const PcssShape& shape, const PcssPoints& points,
                    float* visibility, size_t n, uint64_t& reads, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(PcssVisibilitySimd)(face, shape, points, visibility, n, reads);
  } else {
    pcssVisibilityScalar(face, shape, points, visibility, n, reads);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void pcssVisibility(const PcssFace& face, const PcssShape& shape, const PcssPoints& points,
                    float* visibility, size_t n, uint64_t& reads, bool) {
  pcssVisibilityScalar(face, shape, points, visibility, n, reads);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
