// SIMD twin of edgeAtPixelsScalar (pixel_edges.cpp): the exact test of one edge at up to
// kEdgeLanes points, a point per lane, in double (Highway, dispatched at run time). The same
// operations in the same order as the scalar edgeSector and silhouetteWeight, so the same
// results: glm's dot is (x + y) + z, std::max(a, b) is a < b ? b : a, std::clamp(v, 0, 1) is
// v < 0 ? 0 : 1 < v ? 1 : v, and float() rounds to nearest as DemoteTo would (done per lane
// when the results are stored). A lane stops where the scalar test returns false; its other
// values are computed anyway and never read.
#include "shadows/exact/pixel_edges.h"

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/exact/pixel_edges_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DD = hn::CappedTag<double, kEdgeLanes>;
using VD = hn::Vec<DD>;
using MD = hn::Mask<DD>;

struct V3 {
  VD x, y, z;
};

HWY_INLINE V3 Set3(const dvec3& v) {
  const DD d;
  return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)};
}
HWY_INLINE V3 Sub3(const V3& a, const V3& b) {
  return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
HWY_INLINE V3 Select3(MD m, const V3& yes, const V3& no) {
  return {hn::IfThenElse(m, yes.x, no.x), hn::IfThenElse(m, yes.y, no.y),
          hn::IfThenElse(m, yes.z, no.z)};
}
// glm::dot of two dvec3: (a.x b.x + a.y b.y) + a.z b.z.
HWY_INLINE VD Dot(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}
// std::max(a, b).
HWY_INLINE VD StdMax(VD a, VD b) { return hn::IfThenElse(hn::Lt(a, b), b, a); }
// pseudoAngle (core/pseudo_angle.h).
HWY_INLINE VD PseudoAngle(VD x, VD y) {
  const DD d;
  const VD zero = hn::Zero(d);
  const VD sum = hn::Add(hn::Abs(x), hn::Abs(y));
  const VD p = hn::Div(y, sum);
  const VD angle = hn::IfThenElse(hn::Ge(x, zero),
                                  hn::IfThenElse(hn::Ge(p, zero), p, hn::Add(hn::Set(d, 4.0), p)),
                                  hn::Sub(hn::Set(d, 2.0), p));
  return hn::IfThenElse(hn::Gt(sum, zero), angle, zero);
}

uint32_t EdgeAtPixelsSimd(const PotentialEdge& e, const EdgeTriangle* triangles,
                          const PixelLanes& pixels, EdgeLanes& out) {
  const DD d;
  const size_t lanes = hn::Lanes(d);
  const VD zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const VD two = hn::Set(d, 2.0), four = hn::Set(d, 4.0);
  const V3 edge_a = Set3(e.a), edge_b = Set3(e.b);
  uint32_t accepted = 0;
  out.deferred = 0;
  for (size_t base = 0; base < size_t(pixels.count); base += lanes) {
    const MD in = hn::FirstN(d, size_t(pixels.count) - base);
    auto load = [&](const double* values) { return hn::MaskedLoad(in, d, values + base); };
    const V3 p{load(pixels.px), load(pixels.py), load(pixels.pz)};
    const V3 axis{load(pixels.ax), load(pixels.ay), load(pixels.az)};
    const V3 tangent{load(pixels.tx), load(pixels.ty), load(pixels.tz)};
    const V3 bitangent{load(pixels.bx), load(pixels.by), load(pixels.bz)};
    const VD z_min = load(pixels.z_min), light_radius = load(pixels.light_radius);
    const VD primitive = load(pixels.primitive);
    V3 a = Sub3(edge_a, p), b = Sub3(edge_b, p);
    VD za = Dot(a, axis), zb = Dot(b, axis);
    MD live = hn::AndNot(hn::And(hn::Le(za, z_min), hn::Le(zb, z_min)), in);
    if (hn::AllFalse(d, live)) continue;
    // silhouetteWeight, in double (small integers, exact). A lane where a triangle cutting the
    // light fails the quick test is deferred (and stops here).
    const VD limit = hn::Mul(load(pixels.light_near), hn::Set(d, 1.0 - 1e-9));
    const VD z_ends = StdMax(za, zb);
    MD deferred = hn::Lt(zero, zero);  // all false
    VD weight = zero;
    for (uint32_t k = 0; k < e.triangle_count; ++k) {
      const EdgeTriangle& t = triangles[e.first_triangle + k];
      const MD own = hn::Eq(primitive, hn::Set(d, double(t.id)));
      const VD at_p = hn::Add(Dot(Set3(t.normal), p), hn::Set(d, t.offset));
      const MD positive = hn::Gt(at_p, zero), negative = hn::Lt(at_p, zero);
      MD skip = own;
      if (t.cuts) {
        const VD z_opposite = Dot(Sub3(Set3(t.opposite), p), axis);
        deferred = hn::Or(deferred, hn::AndNot(own, hn::Not(hn::Lt(StdMax(z_ends, z_opposite),
                                                                   limit))));
      } else {
        skip = hn::Or(skip, t.light_above ? positive : hn::Not(positive));
      }
      const VD sign = hn::IfThenElse(positive, one, hn::IfThenElseZero(negative, hn::Neg(one)));
      weight = hn::IfThenElse(skip, weight,
                              hn::Sub(weight, hn::Mul(hn::Set(d, double(t.winding)), sign)));
    }
    deferred = hn::And(deferred, live);
    if (!hn::AllFalse(d, deferred)) {
      HWY_ALIGN uint8_t bits[8] = {};
      hn::StoreMaskBits(d, deferred, bits);
      out.deferred |= uint32_t(bits[0]) << base;
      live = hn::AndNot(deferred, live);
    }
    live = hn::AndNot(hn::Eq(weight, zero), live);
    if (hn::AllFalse(d, live)) continue;
    // edgeSector: the clip to z >= z_min (at most one end: the other lies in front).
    const MD clip_a = hn::Lt(za, z_min);
    const MD clip_b = hn::AndNot(clip_a, hn::Lt(zb, z_min));
    const VD along_a = hn::Div(hn::Sub(z_min, za), hn::Sub(zb, za));
    const VD along_b = hn::Div(hn::Sub(z_min, zb), hn::Sub(za, zb));
    const V3 a_clipped{hn::Add(a.x, hn::Mul(hn::Sub(b.x, a.x), along_a)),
                       hn::Add(a.y, hn::Mul(hn::Sub(b.y, a.y), along_a)),
                       hn::Add(a.z, hn::Mul(hn::Sub(b.z, a.z), along_a))};
    const V3 b_clipped{hn::Add(b.x, hn::Mul(hn::Sub(a.x, b.x), along_b)),
                       hn::Add(b.y, hn::Mul(hn::Sub(a.y, b.y), along_b)),
                       hn::Add(b.z, hn::Mul(hn::Sub(a.z, b.z), along_b))};
    a = Select3(clip_a, a_clipped, a);
    b = Select3(clip_b, b_clipped, b);
    za = hn::IfThenElse(clip_a, z_min, za);
    zb = hn::IfThenElse(clip_b, z_min, zb);
    const VD a2x = hn::Div(Dot(a, tangent), za), a2y = hn::Div(Dot(a, bitangent), za);
    const VD b2x = hn::Div(Dot(b, tangent), zb), b2y = hn::Div(Dot(b, bitangent), zb);
    // Distance from the centre to the projected segment.
    const VD abx = hn::Sub(b2x, a2x), aby = hn::Sub(b2y, a2y);
    const VD ab2 = hn::Add(hn::Mul(abx, abx), hn::Mul(aby, aby));
    VD along = hn::Div(hn::Neg(hn::Add(hn::Mul(a2x, abx), hn::Mul(a2y, aby))), ab2);
    along = hn::IfThenElse(hn::Lt(along, zero), zero,
                           hn::IfThenElse(hn::Lt(one, along), one, along));
    along = hn::IfThenElse(hn::Gt(ab2, zero), along, zero);
    const VD qx = hn::Add(a2x, hn::Mul(along, abx)), qy = hn::Add(a2y, hn::Mul(along, aby));
    const VD distance = hn::Sqrt(hn::Add(hn::Mul(qx, qx), hn::Mul(qy, qy)));
    live = hn::AndNot(hn::Gt(distance, light_radius), live);
    if (hn::AllFalse(d, live)) continue;
    // Sector lines through the centre and each projected end.
    const VD sa = hn::Neg(Dot(a, bitangent)), ua = Dot(a, tangent);
    const VD scale_a = StdMax(hn::Abs(sa), hn::Abs(ua));
    const VD lax = hn::Div(sa, scale_a), lay = hn::Div(ua, scale_a);
    const VD sb = hn::Neg(Dot(b, bitangent)), ub = Dot(b, tangent);
    const VD scale_b = StdMax(hn::Abs(sb), hn::Abs(ub));
    const VD lbx = hn::Div(sb, scale_b), lby = hn::Div(ub, scale_b);
    const VD a_at_b = hn::Add(hn::Mul(lax, b2x), hn::Mul(lay, b2y));
    const VD b_at_a = hn::Add(hn::Mul(lbx, a2x), hn::Mul(lby, a2y));
    live = hn::AndNot(hn::Or(hn::Eq(a_at_b, zero), hn::Eq(b_at_a, zero)), live);
    if (hn::AllFalse(d, live)) continue;
    // The edge's line: glm::cross(a, b), then its plane's values.
    const V3 n{hn::Sub(hn::Mul(a.y, b.z), hn::Mul(b.y, a.z)),
               hn::Sub(hn::Mul(a.z, b.x), hn::Mul(b.z, a.x)),
               hn::Sub(hn::Mul(a.x, b.y), hn::Mul(b.x, a.y))};
    const VD lx = Dot(n, tangent), ly = Dot(n, bitangent), lz = Dot(n, axis);
    const VD l_scale = StdMax(StdMax(hn::Abs(lx), hn::Abs(ly)), hn::Abs(lz));
    // The sector's angles, the shorter way round.
    const VD angle_a = PseudoAngle(a2x, a2y), angle_b = PseudoAngle(b2x, b2y);
    VD turn = hn::Sub(angle_b, angle_a);
    turn = hn::IfThenElse(hn::Gt(turn, two), hn::Sub(turn, four), turn);
    turn = hn::IfThenElse(hn::Le(turn, hn::Neg(two)), hn::Add(turn, four), turn);
    const MD forward = hn::Ge(turn, zero);
    const VD from = hn::IfThenElse(forward, angle_a, angle_b);
    const VD to = hn::IfThenElse(forward, hn::Add(angle_a, turn), hn::Sub(angle_b, turn));
    // The live lanes' results, lane by lane.
    HWY_ALIGN double v[12][kEdgeLanes];
    const VD results[12] = {lax,    lay,    lbx, lby, a_at_b, b_at_a, hn::Div(lx, l_scale),
                            hn::Div(ly, l_scale), hn::Div(lz, l_scale), weight, from, to};
    for (int r = 0; r < 12; ++r) hn::Store(results[r], d, v[r]);
    HWY_ALIGN uint8_t bits[8] = {};
    hn::StoreMaskBits(d, live, bits);
    for (uint32_t mask = bits[0]; mask != 0; mask &= mask - 1) {
      const int k = __builtin_ctz(mask);
      const size_t lane = base + size_t(k);
      SampleEdge& edge = out.edge[lane];
      edge.sector_a[0] = float(v[0][k]);
      edge.sector_a[1] = float(v[1][k]);
      edge.sector_b[0] = float(v[2][k]);
      edge.sector_b[1] = float(v[3][k]);
      edge.a_side = v[4][k] > 0.0;
      edge.b_side = v[5][k] > 0.0;
      edge.line[0] = float(v[6][k]);
      edge.line[1] = float(v[7][k]);
      edge.line[2] = float(v[8][k]);
      edge.centre_side = edge.line[2] >= 0.0f;
      const int32_t w = int32_t(v[9][k]);
      edge.delta = edge.centre_side ? -w : w;
      out.weight[lane] = w;
      out.from[lane] = v[10][k];
      out.to[lane] = v[11][k];
      accepted |= 1u << lane;
    }
  }
  return accepted;
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(EdgeAtPixelsSimd);

uint32_t edgeAtPixels(const PotentialEdge& e, const EdgeTriangle* triangles,
                      const PixelLanes& pixels, const SortedSamples& samples, EdgeLanes& out,
                      bool simd) {
  if (!useSimd(simd)) return edgeAtPixelsScalar(e, triangles, pixels, samples, out);
  const uint32_t passed = HWY_DYNAMIC_DISPATCH(EdgeAtPixelsSimd)(e, triangles, pixels, out);
  // The lanes' runs, all at once (sampleRunsBatch); those of lanes that did not pass are
  // never read (their ranges are a previous call's, or 0).
  if (passed != 0) sampleRunsBatch(samples, out.from, out.to, pixels.count, out.runs, true);
  return passed;
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

uint32_t edgeAtPixels(const PotentialEdge& e, const EdgeTriangle* triangles,
                      const PixelLanes& pixels, const SortedSamples& samples, EdgeLanes& out,
                      bool) {
  return edgeAtPixelsScalar(e, triangles, pixels, samples, out);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
