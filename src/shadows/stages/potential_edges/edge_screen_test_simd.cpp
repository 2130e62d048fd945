// SIMD twin of edge_screen_test_scalar.cpp (Highway, dispatched at run time): 4 to 16 pixels
// per step, the same float operations in the same order.
#include "shadows/stages/potential_edges/edge_screen_test.h"

#include <algorithm>

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/stages/potential_edges/edge_screen_test_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The mask's lanes as bits, lane 0 lowest.
template <class D, class M>
HWY_INLINE uint64_t MaskBits(D d, M mask) {
  HWY_ALIGN uint8_t bits[8] = {};
  hn::StoreMaskBits(d, mask, bits);
  uint64_t out = 0;
  for (size_t b = 0; b < (hn::Lanes(d) + 7) / 8; ++b) out |= uint64_t(bits[b]) << (8 * b);
  return out;
}

// `weight` plus w in the lanes where `where` holds (a float mask).
template <class DI, class V, class M>
HWY_INLINE V AddWhere(DI di, V weight, M where, int32_t w) {
  return hn::Add(weight, hn::IfThenElseZero(hn::RebindMask(di, where), hn::Set(di, w)));
}

// The lanes of `keep` that may see the edge as a silhouette: a triangle's sign unknown, or the
// included triangles' weights not cancelling.
template <class DF, class DI, class M, class V>
HWY_INLINE M MaySeeSilhouette(DF df, DI di, M keep, M unknown, V weight) {
  return hn::And(keep, hn::Or(unknown, hn::RebindMask(df, hn::Ne(weight, hn::Zero(di)))));
}

uint64_t EdgeCandidatesSimd(const EdgeScreenTest& t, const PixelBlock& block) {
  const hn::CappedTag<float, 16> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t lanes = hn::Lanes(df);
  uint64_t out = 0;
  for (size_t i = 0; i < size_t(kBlockPixels); i += lanes) {
    const uint64_t active = (block.active >> i) & (lanes >= 64 ? ~0ull : ((1ull << lanes) - 1));
    if (active == 0) continue;
    const auto sx = hn::Load(df, block.sx + i);
    const auto sy = hn::Load(df, block.sy + i);
    const auto z = hn::Load(df, block.z + i);
    const auto offset = hn::Load(df, block.offset + i);
    // ((a sx + b sy) + c z) + d, as the scalar twin.
    auto planeAt = [&](const float* p) {
      return hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(df, p[0]), sx),
                                     hn::Mul(hn::Set(df, p[1]), sy)),
                             hn::Mul(hn::Set(df, p[2]), z)),
                     hn::Set(df, p[3]));
    };
    // Most pixels of a binned tile lie outside the edge's thin region: once every lane is out,
    // the remaining planes cannot bring one back (the scalar twin stops per pixel the same way).
    auto keep = hn::FirstN(df, lanes);  // all true
    for (int k = 0; k < t.region_count; ++k) {
      keep = hn::And(keep, hn::Ge(planeAt(t.region[k]),
                                  hn::Neg(hn::Add(hn::Set(df, t.region_margin[k]), offset))));
      if (hn::AllFalse(df, keep)) break;
    }
    if (hn::AllFalse(df, keep)) continue;
    if (t.triangle_count > 0) {
      auto unknown = hn::FirstN(df, 0);  // all false
      auto weight = hn::Zero(di);
      // (v0 qx + v1 qy) + v2 qz, as the scalar twin.
      auto depth = [&](const float* v) {
        return hn::Add(hn::Add(hn::Mul(hn::Set(df, v[0]), hn::Load(df, block.qx + i)),
                               hn::Mul(hn::Set(df, v[1]), hn::Load(df, block.qy + i))),
                       hn::Mul(hn::Set(df, v[2]), hn::Load(df, block.qz + i)));
      };
      for (int k = 0; k < t.triangle_count; ++k) {
        const auto e = planeAt(t.triangle[k]);
        const auto margin = hn::Add(hn::Set(df, t.triangle_margin[k]), offset);
        const auto positive = hn::Gt(e, margin);
        const auto negative = hn::Lt(e, hn::Neg(margin));
        unknown = hn::Or(unknown, hn::Not(hn::Or(positive, negative)));
        if (t.cuts[k] && !block.has_q) {
          unknown = hn::FirstN(df, lanes);  // all true: no proof without q
        } else if (t.cuts[k]) {
          const auto deepest =
              hn::Max(hn::Max(depth(t.ends[0]), depth(t.ends[1])), depth(t.opposite[k]));
          const auto in_front = hn::Lt(
              hn::Add(hn::Add(deepest, hn::Load(df, block.reach + i)),
                      hn::Mul(hn::Load(df, block.slack + i), hn::Set(df, t.cut_extent[k]))),
              hn::Zero(df));
          unknown = hn::Or(unknown, hn::Not(in_front));
          weight = AddWhere(di, weight, positive, t.weight[k]);
          weight = AddWhere(di, weight, negative, -t.weight[k]);
        } else {
          weight = AddWhere(di, weight, t.light_above[k] ? negative : positive, t.weight[k]);
        }
      }
      keep = MaySeeSilhouette(df, di, keep, unknown, weight);
    }
    out |= (MaskBits(df, keep) & active) << i;
  }
  return out;
}

int EdgeTileCandidatesSimd(const EdgeScreenTest& t, const EdgeTileBox& box, uint32_t* kept,
                           int& tested) {
  const hn::CappedTag<float, 16> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t lanes = hn::Lanes(df);
  int count = 0;
  tested = 0;
  const auto zero = hn::Zero(df);
  const auto last_centre = hn::Set(df, float(box.width) - 0.5f);
  const auto size = hn::Set(df, float(box.size)), half = hn::Set(df, 0.5f);
  const auto span = hn::Set(df, float(box.size - 1));
  const auto lane_index = hn::Iota(df, 0.0f);
  const bool signs = t.triangle_count > 0 && !t.any_cuts;
  // Per plane, the thresholds -(margin + offset) and margin + offset, as the scalar twin.
  float region_bound[kMaxRegionPlanes], triangle_bound[4];
  for (int k = 0; k < t.region_count; ++k) region_bound[k] = -(t.region_margin[k] + box.offset);
  for (int k = 0; k < t.triangle_count; ++k) triangle_bound[k] = t.triangle_margin[k] + box.offset;
  for (int ty = box.ty0; ty <= box.ty1; ++ty) {
    const auto y0 = hn::Set(df, float(ty * box.size) + 0.5f);
    const auto y1 = hn::Set(df, float(std::min(ty * box.size + box.size, box.height)) - 0.5f);
    const size_t row = size_t(ty) * size_t(box.columns);
    for (int tx = box.tx0; tx <= box.tx1; tx += int(lanes)) {
      const size_t n = std::min(lanes, size_t(box.tx1 - tx + 1));
      const auto in_row = hn::FirstN(df, n);
      // Lanes past the box's row read the next tiles (or the arrays' padding): masked off.
      const auto zmin = hn::LoadU(df, box.zmin + row + size_t(tx));
      const auto zmax = hn::LoadU(df, box.zmax + row + size_t(tx));
      // float(tx * size) + 0.5 lane by lane, as the scalar twin (exact: small integers).
      const auto x0 = hn::Add(hn::Mul(hn::Add(lane_index, hn::Set(df, float(tx))), size), half);
      const auto x1 = hn::Min(hn::Add(x0, span), last_centre);
      const auto covered = hn::And(in_row, hn::Gt(zmax, zero));
      tested += int(hn::CountTrue(df, covered));
      if (hn::AllFalse(df, covered)) continue;
      auto atDepths = [&](const float* p, bool high, hn::Vec<decltype(df)> lo,
                           hn::Vec<decltype(df)> hi) {
        const auto x = (p[0] >= 0.0f) == high ? x1 : x0;
        const auto y = (p[1] >= 0.0f) == high ? y1 : y0;
        const auto z = (p[2] >= 0.0f) == high ? hi : lo;
        return hn::Add(
            hn::Add(hn::Add(hn::Mul(hn::Set(df, p[0]), x), hn::Mul(hn::Set(df, p[1]), y)),
                    hn::Mul(hn::Set(df, p[2]), z)),
            hn::Set(df, p[3]));
      };
      auto at = [&](const float* p, bool high) { return atDepths(p, high, zmin, zmax); };
      // The lanes of `keep` whose box over depths [lo, hi] is within every region plane. Every
      // plane, without stopping once no lane is left: where that happens varies from edge to
      // edge and row to row, and the branch was mispredicted more often than the planes it
      // saved cost (the results are the same).
      auto regionMeets = [&](hn::Mask<decltype(df)> keep, hn::Vec<decltype(df)> lo,
                              hn::Vec<decltype(df)> hi) {
        for (int k = 0; k < t.region_count; ++k)
          keep = hn::And(keep, hn::Ge(atDepths(t.region[k], true, lo, hi),
                                      hn::Set(df, region_bound[k])));
        return keep;
      };
      auto keep = covered;
      if (box.parts != nullptr) {
        // A part passing implies the whole range passes (its box lies inside): the parts alone.
        const size_t i = row + size_t(tx);
        const EdgeTileParts& parts = *box.parts;
        const auto low_max = hn::LoadU(df, parts.low_zmax + i);
        const auto high_max = hn::LoadU(df, parts.high_zmax + i);
        const auto low = regionMeets(hn::And(keep, hn::Gt(low_max, zero)),
                                     hn::LoadU(df, parts.low_zmin + i), low_max);
        const auto high = regionMeets(hn::And(keep, hn::Gt(high_max, zero)),
                                      hn::LoadU(df, parts.high_zmin + i), high_max);
        keep = hn::Or(low, high);
      } else {
        keep = regionMeets(covered, zmin, zmax);
      }
      if (signs && !hn::AllFalse(df, keep)) {
        auto unknown = hn::FirstN(df, 0);
        auto weight = hn::Zero(di);
        for (int k = 0; k < t.triangle_count; ++k) {
          const auto positive =
              hn::Gt(at(t.triangle[k], false), hn::Set(df, triangle_bound[k]));
          const auto negative =
              hn::Lt(at(t.triangle[k], true), hn::Set(df, -triangle_bound[k]));
          unknown = hn::Or(unknown, hn::Not(hn::Or(positive, negative)));
          weight = AddWhere(di, weight, t.light_above[k] ? negative : positive, t.weight[k]);
        }
        keep = MaySeeSilhouette(df, di, keep, unknown, weight);
      }
      for (uint64_t mask = MaskBits(df, keep); mask != 0; mask &= mask - 1)
        kept[count++] = uint32_t(row) + uint32_t(tx + __builtin_ctzll(mask));
    }
  }
  return count;
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(EdgeCandidatesSimd);
HWY_EXPORT(EdgeTileCandidatesSimd);

uint64_t edgeCandidates(const EdgeScreenTest& test, const PixelBlock& block, bool simd) {
  if (useSimd(simd)) return HWY_DYNAMIC_DISPATCH(EdgeCandidatesSimd)(test, block);
  return edgeCandidatesScalar(test, block);
}

int edgeTileCandidates(const EdgeScreenTest& test, const EdgeTileBox& box, uint32_t* kept,
                       int& tested, bool simd) {
  if (useSimd(simd)) return HWY_DYNAMIC_DISPATCH(EdgeTileCandidatesSimd)(test, box, kept, tested);
  return edgeTileCandidatesScalar(test, box, kept, tested);
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

uint64_t edgeCandidates(const EdgeScreenTest& test, const PixelBlock& block, bool) {
  return edgeCandidatesScalar(test, block);
}

int edgeTileCandidates(const EdgeScreenTest& test, const EdgeTileBox& box, uint32_t* kept,
                       int& tested, bool) {
  return edgeTileCandidatesScalar(test, box, kept, tested);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
