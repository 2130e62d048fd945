// SIMD twin of shading_kernel_scalar.cpp, compiled once per CPU target by Highway and chosen at
// run time (HWY_DYNAMIC_DISPATCH). Same steps, same operation order, same results. A step
// shades one vector of consecutive pixels of a row; lanes showing different triangles get
// their own triangle's record (a few records per step at most: neighbours mostly share one).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/simd_dispatch.h"
#include "raster/depth_buffer.h"
#include "render/shading_kernel.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shading_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using MF = hn::Mask<DF>;

struct V3 {
  VF x, y, z;
};

HWY_INLINE V3 Set3(const vec3& v) {
  const DF df;
  return {hn::Set(df, v.x), hn::Set(df, v.y), hn::Set(df, v.z)};
}
HWY_INLINE V3 Blend3(MF m, const vec3& v, const V3& old) {
  const DF df;
  return {hn::IfThenElse(m, hn::Set(df, v.x), old.x), hn::IfThenElse(m, hn::Set(df, v.y), old.y),
          hn::IfThenElse(m, hn::Set(df, v.z), old.z)};
}
HWY_INLINE V3 Select3(MF m, const V3& yes, const V3& no) {
  return {hn::IfThenElse(m, yes.x, no.x), hn::IfThenElse(m, yes.y, no.y),
          hn::IfThenElse(m, yes.z, no.z)};
}
// (x + y) + z, as the scalar twin's dot3.
HWY_INLINE VF Dot3(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// The triangles of one step's valid lanes: `first` for every lane but those of the `others`,
// each with its lanes' mask. Lane attributes are assembled only when a step needs them (flat
// triangles need no barycentrics, diffuse ones no specular terms), as broadcasts when the step
// shows one triangle.
struct StepTriangles {
  const ShadingTriangle* first = nullptr;
  size_t others = 0;
  const ShadingTriangle* other[kMaxLanes];
  MF mask[kMaxLanes];
  ShadingTriangle scratch[kMaxLanes];  // ShadingTriangleTable::get's, one per triangle
};

HWY_INLINE V3 Lanes3(const StepTriangles& s, vec3 ShadingTriangle::*field) {
  V3 v = Set3(s.first->*field);
  for (size_t i = 0; i < s.others; ++i) v = Blend3(s.mask[i], s.other[i]->*field, v);
  return v;
}
HWY_INLINE VF LanesF(const StepTriangles& s, float ShadingTriangle::*field) {
  const DF df;
  VF v = hn::Set(df, s.first->*field);
  for (size_t i = 0; i < s.others; ++i)
    v = hn::IfThenElse(s.mask[i], hn::Set(df, s.other[i]->*field), v);
  return v;
}
HWY_INLINE VI LanesI(const StepTriangles& s, int32_t ShadingTriangle::*field) {
  const DI di;
  VI v = hn::Set(di, s.first->*field);
  for (size_t i = 0; i < s.others; ++i)
    v = hn::IfThenElse(hn::RebindMask(di, s.mask[i]), hn::Set(di, s.other[i]->*field), v);
  return v;
}
// The valid lanes whose triangle has `flag` set.
HWY_INLINE MF LanesFlag(const StepTriangles& s, bool ShadingTriangle::*flag, MF valid) {
  MF m = s.first->*flag ? valid : hn::And(valid, hn::Not(valid));
  for (size_t i = 0; i < s.others; ++i)
    m = s.other[i]->*flag ? hn::Or(m, s.mask[i]) : hn::AndNot(s.mask[i], m);
  return m;
}

// (n.h)^exponent lane by lane, as the scalar twin's specularPower: repeated squaring for
// integer exponents, std::pow for the lanes (in `needed`) whose shininess is not one.
HWY_INLINE VF SpecularPower(VF n_dot_h, const StepTriangles& s, MF needed) {
  const DF df;
  const DI di;
  const VI zero_i = hn::Zero(di), one_i = hn::Set(di, 1);
  const VI exponent = LanesI(s, &ShadingTriangle::exponent);
  const auto fractional_i = hn::Lt(exponent, zero_i);
  VI e = hn::IfThenZeroElse(fractional_i, exponent);
  VF result = hn::Set(df, 1.0f), base = n_dot_h;
  while (!hn::AllTrue(di, hn::Eq(e, zero_i))) {
    const auto odd = hn::RebindMask(df, hn::Eq(hn::And(e, one_i), one_i));
    result = hn::IfThenElse(odd, hn::Mul(result, base), result);
    base = hn::Mul(base, base);
    e = hn::ShiftRight<1>(e);
  }
  const MF fractional = hn::And(hn::RebindMask(df, fractional_i), needed);
  if (!hn::AllFalse(df, fractional)) {
    alignas(HWY_MAX_BYTES) float base_lanes[kMaxLanes], shininess[kMaxLanes], power[kMaxLanes];
    hn::Store(n_dot_h, df, base_lanes);
    hn::Store(LanesF(s, &ShadingTriangle::shininess), df, shininess);
    hn::Store(result, df, power);
    for (size_t i = 0; i < hn::Lanes(df); ++i) power[i] = std::pow(base_lanes[i], shininess[i]);
    result = hn::IfThenElse(fractional, hn::Load(df, power), result);
  }
  return result;
}

// The triangle records of a step's valid lanes (ShadingTriangleTable::get): the first valid
// lane's triangle, then the others'.
HWY_INLINE void GatherStepTriangles(const uint32_t* ids_at, hn::Vec<DU> ids, MF valid,
                                    ShadingTriangleTable& triangles, StepTriangles& tris) {
  const DF df;
  const DU du;
  auto remaining = hn::RebindMask(du, valid);
  {
    const uint32_t id = ids_at[size_t(hn::FindFirstTrue(du, remaining))];
    tris.first = &triangles.get(id, tris.scratch[0]);
    tris.others = 0;
    remaining = hn::AndNot(hn::Eq(ids, hn::Set(du, id)), remaining);
  }
  while (!hn::AllFalse(du, remaining)) {
    const uint32_t id = ids_at[size_t(hn::FindFirstTrue(du, remaining))];
    const auto same = hn::Eq(ids, hn::Set(du, id));
    tris.other[tris.others] = &triangles.get(id, tris.scratch[tris.others + 1]);
    tris.mask[tris.others++] = hn::RebindMask(df, same);
    remaining = hn::AndNot(same, remaining);
  }
}

// Step 2: the shading normal at p. A flat triangle's is n0; otherwise the corner normals are
// interpolated with barycentrics clamped to the triangle (the unprojected point is on it only
// up to depth rounding, and a point just outside must not extrapolate), then normalised, which
// also removes the clamped weights' sum. Lanes: the interpolation is skipped when every valid
// lane's triangle is flat.
HWY_INLINE V3 ShadingNormal(const StepTriangles& tris, const V3& p, const V3& n0,
                            const V3& geometric, MF valid) {
  const DF df;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const MF flat = LanesFlag(tris, &ShadingTriangle::flat, valid);
  if (hn::AllFalse(df, hn::AndNot(flat, valid))) return n0;
  const V3 a = Lanes3(tris, &ShadingTriangle::a);
  const V3 ep{hn::Sub(p.x, a.x), hn::Sub(p.y, a.y), hn::Sub(p.z, a.z)};
  const VF v_plane = Dot3(ep, Lanes3(tris, &ShadingTriangle::gv));
  const VF w_plane = Dot3(ep, Lanes3(tris, &ShadingTriangle::gw));
  VF u = hn::Max(hn::Sub(hn::Sub(one, v_plane), w_plane), zero);
  const VF v = hn::Max(v_plane, zero), w = hn::Max(w_plane, zero);
  u = hn::IfThenElse(hn::Gt(hn::Add(hn::Add(u, v), w), zero), u, one);
  const V3 n1 = Lanes3(tris, &ShadingTriangle::n1), n2 = Lanes3(tris, &ShadingTriangle::n2);
  const V3 interpolated{hn::Add(hn::Add(hn::Mul(u, n0.x), hn::Mul(v, n1.x)), hn::Mul(w, n2.x)),
                        hn::Add(hn::Add(hn::Mul(u, n0.y), hn::Mul(v, n1.y)), hn::Mul(w, n2.y)),
                        hn::Add(hn::Add(hn::Mul(u, n0.z), hn::Mul(v, n1.z)), hn::Mul(w, n2.z))};
  const VF length2 = Dot3(interpolated, interpolated);
  const VF inv_length = hn::Div(one, hn::Sqrt(length2));
  const V3 smooth = Select3(
      hn::Gt(length2, hn::Set(df, 1e-20f)),
      V3{hn::Mul(interpolated.x, inv_length), hn::Mul(interpolated.y, inv_length),
         hn::Mul(interpolated.z, inv_length)},
      geometric);
  return Select3(flat, n0, smooth);
}

// Step 5 for one light: its diffuse and specular term times its visibility `vis`, added to
// `lit` in the lanes it reaches.
HWY_INLINE void AddShadingLight(const ShadingLight& light, const StepTriangles& tris, VF vis,
                                const V3& p, const V3& n, const V3& view, const V3& albedo,
                                MF valid, MF specular, V3& lit) {
  const DF df;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const V3 center = Set3(light.center);
  const V3 to_light{hn::Sub(center.x, p.x), hn::Sub(center.y, p.y), hn::Sub(center.z, p.z)};
  const VF distance2 = Dot3(to_light, to_light);
  const VF n_dot_to_light = Dot3(n, to_light);
  // Facing away: neither diffuse nor specular.
  const MF facing = hn::And(hn::Gt(distance2, zero), hn::Gt(n_dot_to_light, zero));
  const MF lit_lanes = hn::And(hn::And(valid, hn::Gt(vis, zero)), facing);
  if (hn::AllFalse(df, lit_lanes)) return;
  const VF inv_distance = hn::Div(one, hn::Sqrt(distance2));
  const VF diffuse = hn::Mul(n_dot_to_light, inv_distance);
  V3 reflected{hn::Mul(albedo.x, diffuse), hn::Mul(albedo.y, diffuse),
               hn::Mul(albedo.z, diffuse)};
  const MF specular_lanes = hn::And(specular, lit_lanes);
  if (!hn::AllFalse(df, specular_lanes)) {
    const V3 h{hn::Add(hn::Mul(to_light.x, inv_distance), view.x),
               hn::Add(hn::Mul(to_light.y, inv_distance), view.y),
               hn::Add(hn::Mul(to_light.z, inv_distance), view.z)};
    const VF h_length2 = Dot3(h, h);
    const VF n_dot_h = hn::IfThenElseZero(
        hn::Gt(h_length2, zero),
        hn::Mul(hn::Max(Dot3(n, h), zero), hn::Div(one, hn::Sqrt(h_length2))));
    const VF power = SpecularPower(n_dot_h, tris, specular_lanes);
    const V3 specular_color = Lanes3(tris, &ShadingTriangle::specular);
    reflected = Select3(specular_lanes,
                        V3{hn::Add(reflected.x, hn::Mul(specular_color.x, power)),
                           hn::Add(reflected.y, hn::Mul(specular_color.y, power)),
                           hn::Add(reflected.z, hn::Mul(specular_color.z, power))},
                        reflected);
  }
  const VF weight = hn::Min(vis, one);
  const V3 radiance = Set3(light.radiance);
  lit = Select3(lit_lanes,
                V3{hn::Add(lit.x, hn::Mul(hn::Mul(reflected.x, radiance.x), weight)),
                   hn::Add(lit.y, hn::Mul(hn::Mul(reflected.y, radiance.y), weight)),
                   hn::Add(lit.z, hn::Mul(hn::Mul(reflected.z, radiance.z), weight))},
                lit);
}

void ShadeRowSimd(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out) {
  const DF df;
  const DU du;
  const size_t lanes = hn::Lanes(df);
  const size_t row_pixel = size_t(y) * size_t(frame.width);
  const float* depth_row = frame.depth + row_pixel;
  const uint32_t* id_row = frame.primitive + row_pixel;
  const vec3 row_ray = frame.ray_origin + frame.ray_dy * (float(y) + 0.5f);
  const V3 row_ray_v = Set3(row_ray), ray_dx = Set3(frame.ray_dx), eye = Set3(frame.eye);
  const V3 background = Set3(frame.background);
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), half = hn::Set(df, 0.5f);
  const VF near_plane = hn::Set(df, frame.near_plane);
  const auto no_primitive = hn::Set(du, kNoPrimitive);
  StepTriangles tris;
  for (size_t x = 0; x < size_t(frame.width); x += lanes) {
    const size_t count = std::min(lanes, size_t(frame.width) - x);
    {
      constexpr size_t kAhead = 128;  // pixels
      if (x + kAhead < size_t(frame.width)) {
        __builtin_prefetch(id_row + x + kAhead);
        __builtin_prefetch(depth_row + x + kAhead);
        for (const ShadingLight& light : frame.lights)
          if (light.visibility) __builtin_prefetch(light.visibility + row_pixel + x + kAhead);
      }
    }
    const auto in_row_u = hn::FirstN(du, count);
    const auto ids = hn::MaskedLoad(in_row_u, du, id_row + x);
    const VF depth = hn::MaskedLoad(hn::RebindMask(df, in_row_u), df, depth_row + x);
    // Depth is reversed-Z (core/view.h): > 0 wherever a triangle was drawn.
    const auto valid_u = hn::AndNot(hn::Eq(ids, no_primitive), in_row_u);
    const MF valid = hn::And(hn::RebindMask(df, valid_u), hn::Gt(depth, zero));
    V3 color = background;
    if (!hn::AllFalse(df, valid)) {
      GatherStepTriangles(id_row + x, ids, valid, triangles, tris);
      // Step 1: the view ray and the visible point on it.
      const VF fx = hn::Add(hn::Iota(df, float(x)), half);
      const V3 ray{hn::Add(row_ray_v.x, hn::Mul(ray_dx.x, fx)),
                   hn::Add(row_ray_v.y, hn::Mul(ray_dx.y, fx)),
                   hn::Add(row_ray_v.z, hn::Mul(ray_dx.z, fx))};
      const VF scale = hn::Div(near_plane, depth);
      const V3 p{hn::Add(eye.x, hn::Mul(ray.x, scale)), hn::Add(eye.y, hn::Mul(ray.y, scale)),
                 hn::Add(eye.z, hn::Mul(ray.z, scale))};
      const V3 geometric = Lanes3(tris, &ShadingTriangle::geometric);
      V3 n = ShadingNormal(tris, p, Lanes3(tris, &ShadingTriangle::n0), geometric, valid);
      // Step 3: turn it to the side the eye sees, as the geometric normal decides (an
      // interpolated normal may lean away from the eye near a silhouette of a front face).
      const V3 flipped{hn::Neg(n.x), hn::Neg(n.y), hn::Neg(n.z)};
      n = Select3(hn::Gt(Dot3(geometric, ray), zero), flipped, n);
      // Step 4: unit direction to the eye, for the half vector.
      const MF specular = LanesFlag(tris, &ShadingTriangle::has_specular, valid);
      V3 view{zero, zero, zero};
      if (!hn::AllFalse(df, specular)) {
        const VF inv_ray = hn::Div(one, hn::Sqrt(Dot3(ray, ray)));
        view = V3{hn::Mul(hn::Neg(ray.x), inv_ray), hn::Mul(hn::Neg(ray.y), inv_ray),
                  hn::Mul(hn::Neg(ray.z), inv_ray)};
      }
      // Step 5: every light's diffuse and specular term times its visibility, onto ambient.
      V3 lit = Lanes3(tris, &ShadingTriangle::ambient);
      const V3 albedo = Lanes3(tris, &ShadingTriangle::albedo);
      for (const ShadingLight& light : frame.lights) {
        const VF vis = light.visibility
                           ? hn::MaskedLoad(valid, df, light.visibility + row_pixel + x)
                           : one;
        AddShadingLight(light, tris, vis, p, n, view, albedo, valid, specular, lit);
      }
      color = Select3(valid, lit, background);
    }
    float* dst = &out[x].x;
    if (count == lanes) {
      hn::StoreInterleaved3(color.x, color.y, color.z, df, dst);
    } else {
      alignas(HWY_MAX_BYTES) float tail[3 * HWY_MAX_BYTES / sizeof(float)];
      hn::StoreInterleaved3(color.x, color.y, color.z, df, tail);
      std::memcpy(dst, tail, count * 3 * sizeof(float));
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(ShadeRowSimd);

void shadeRow(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out,
              bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(ShadeRowSimd)(frame, y, triangles, out);
  } else {
    shadeRowScalar(frame, y, triangles, out);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void shadeRow(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out,
              bool) {
  shadeRowScalar(frame, y, triangles, out);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
