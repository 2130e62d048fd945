// SIMD twins of tile_kernels_scalar.cpp, compiled once per CPU target by Highway and chosen at
// run time (HWY_DYNAMIC_DISPATCH). Same steps, same operation order, same results.
#include "raster/tile_kernels.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/tile_kernels_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

#include "raster/row_spans_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Edge values of one row's first lanes and the per-lane offsets dx * lane, shared by kernels.
struct RowEdges {
  int32_t start[3];
};

template <class DI>
HWY_INLINE auto insideMask(DI di, const TileEdges& e, const RowEdges& row, int rx,
                           const hn::Vec<DI> (&lane_step)[3]) {
  const auto minus_one = hn::Set(di, -1);
  auto m = hn::Gt(hn::Add(hn::Set(di, row.start[0] + e.dx[0] * rx), lane_step[0]), minus_one);
  m = hn::And(m, hn::Gt(hn::Add(hn::Set(di, row.start[1] + e.dx[1] * rx), lane_step[1]), minus_one));
  m = hn::And(m, hn::Gt(hn::Add(hn::Set(di, row.start[2] + e.dx[2] * rx), lane_step[2]), minus_one));
  return m;
}

void DepthKernelSimd(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                     KernelCounts& counts) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const int lanes = int(hn::Lanes(df));
  const auto iota_i = hn::Iota(di, 0);
  const hn::Vec<decltype(di)> lane_step[3] = {hn::Mul(hn::Set(di, e.dx[0]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[1]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[2]), iota_i)};
  const auto id = hn::Set(du, primitive);
  const auto da = hn::Set(df, e.da);
  // No branch on what a vector holds: a dense mesh's triangles are a few pixels wide, and
  // whether a row of one covers a pixel, or passes the depth test, follows no pattern a branch
  // predictor learns; masked loads and stores of an empty mask touch nothing.
  uint64_t covered = 0, writes = 0;
  for (int y = e.y0; y <= e.y1; ++y) {
    const int ry = y - e.ty0;
    const auto row_depth = hn::Set(df, e.dc + e.db * float(ry));
    const RowEdges row{{e.e0[0] + e.dy[0] * ry, e.e0[1] + e.dy[1] * ry, e.e0[2] + e.dy[2] * ry}};
    float* depth_row = target.depth + size_t(y - target.y0) * target.stride;
    uint32_t* id_row = target.primitive + size_t(y - target.y0) * target.stride;
    for (int x = e.x0; x <= e.x1; x += lanes) {
      const int rx = x - e.tx0;
      // Covered: inside all three edges (>= 0).
      const auto in_row = hn::FirstN(di, size_t(e.x1 - x + 1));
      const auto inside_i = hn::And(insideMask(di, e, row, rx, lane_step), in_row);
      const auto inside = hn::RebindMask(df, inside_i);
      covered += hn::CountTrue(df, inside);
      // Depth test: strictly closer (greater reversed-Z) wins, so the first drawn of equal
      // depths stays.
      const auto d = hn::Add(row_depth, hn::Mul(da, hn::Iota(df, float(rx))));
      const auto stored = hn::MaskedLoad(inside, df, depth_row + (x - target.x0));
      const auto write = hn::And(inside, hn::Gt(d, stored));
      writes += hn::CountTrue(df, write);
      // Write depth and primitive id where it passes.
      hn::BlendedStore(d, write, df, depth_row + (x - target.x0));
      hn::BlendedStore(id, hn::RebindMask(du, write), du, id_row + (x - target.x0));
    }
  }
  counts.covered += covered;
  counts.writes += writes;
}

// One vector of StencilRows' row y from column x, its first `count` lanes in the span: the
// covered lanes where the depth rule passes on a surface (and, with owners, the pixel is not
// the owners' own) get the contribution. With kSkip a vector stops as soon as no lane is left
// to draw; without, it runs branch-free to its (possibly empty) masked store. The constants are
// set here from their scalars: inlined, they are hoisted out of the rows' loops.
template <DepthRule kRule, bool kOwned, bool kSkip, class VI, class VF>
HWY_INLINE void StencilVector(const TileEdges& e, int32_t contribution,
                              const StencilTarget& target, StencilOwners owners, int y, int x,
                              size_t count, VI edge0, VI edge1, VI edge2, VF row_depth,
                              uint64_t& covered, uint64_t& writes) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const auto minus_one = hn::Set(di, -1);
  const size_t at = size_t(y - target.y0) * target.stride + size_t(x - target.x0);
  // Covered: inside all three edges (>= 0); lanes past the span are off.
  auto inside_i = hn::And(hn::FirstN(di, count), hn::Gt(edge0, minus_one));
  inside_i = hn::And(inside_i, hn::Gt(edge1, minus_one));
  inside_i = hn::And(inside_i, hn::Gt(edge2, minus_one));
  if (kSkip && hn::AllFalse(di, inside_i)) return;
  const auto inside = hn::RebindMask(df, inside_i);
  covered += hn::CountTrue(df, inside);
  // Depth rule against the stored depth, only where there is a surface (stored depth > 0).
  const auto d = hn::Add(row_depth, hn::Mul(hn::Set(df, e.da), hn::Iota(df, float(x - e.tx0))));
  const auto stored = hn::MaskedLoad(inside, df, target.depth + at);
  const auto pass = [&] {
    if constexpr (kRule == DepthRule::Closer) return hn::Gt(d, stored);
    else return hn::Le(d, stored);
  }();
  auto write = hn::And(hn::And(inside, hn::Gt(stored, hn::Zero(df))), pass);
  if (kSkip && hn::AllFalse(df, write)) return;
  if constexpr (kOwned) {
    const auto write_u = hn::RebindMask(du, write);
    const auto id = hn::MaskedLoad(write_u, du, target.primitive + at);
    write = hn::RebindMask(df, hn::AndNot(hn::Or(hn::Eq(id, hn::Set(du, owners.first)),
                                                 hn::Eq(id, hn::Set(du, owners.second))),
                                          write_u));
    if (kSkip && hn::AllFalse(df, write)) return;
  }
  writes += hn::CountTrue(df, write);
  // Add the contribution to the stencil where both hold.
  const auto write_i = hn::RebindMask(di, write);
  const auto s = hn::MaskedLoad(write_i, di, target.stencil + at);
  hn::BlendedStore(hn::Add(s, hn::Set(di, contribution)), write_i, di, target.stencil + at);
}

// StencilKernelSimd with the depth rule and whether there are owners as constants: as run-time
// values they cost every row of a sliver a test of each (the compiler kept them in memory, and
// chose the rule's mask by moving both comparisons' masks through general registers).
template <DepthRule kRule, bool kOwned>
HWY_INLINE void StencilRows(const TileEdges& e, int32_t contribution, const StencilTarget& target,
                            KernelCounts& counts, StencilOwners owners) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const int lanes = int(hn::Lanes(df));
  const auto iota_i = hn::Iota(di, 0);
  const hn::Vec<decltype(di)> lane_step[3] = {hn::Mul(hn::Set(di, e.dx[0]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[1]), iota_i),
                                              hn::Mul(hn::Set(di, e.dx[2]), iota_i)};
  const RowSpans spans(e);
  int y_lo, y_hi;
  if (!spans.rows(y_lo, y_hi)) return;
  // Counted in registers: through `counts` every vector would be a read-modify-write in memory.
  uint64_t covered = 0, writes = 0;
  // The edge values step by dx * lanes from one vector to the next along a row.
  const hn::Vec<decltype(di)> vector_step[3] = {hn::Set(di, e.dx[0] * lanes),
                                                hn::Set(di, e.dx[1] * lanes),
                                                hn::Set(di, e.dx[2] * lanes)};
  // Each row's span, a batch of rows at a time (row_spans_simd-inl.h).
  BatchedRowSpans row_spans(spans, y_lo, y_hi);
  for (int y = y_lo; y <= y_hi; ++y) {
    int x_lo, x_hi;
    if (!row_spans.at(y, x_lo, x_hi)) continue;
    const int ry = y - e.ty0;
    const auto row_depth = hn::Set(df, e.dc + e.db * float(ry));
    const RowEdges row{{e.e0[0] + e.dy[0] * ry, e.e0[1] + e.dy[1] * ry, e.e0[2] + e.dy[2] * ry}};
    const int rx_lo = x_lo - e.tx0;
    auto edge0 = hn::Add(hn::Set(di, row.start[0] + e.dx[0] * rx_lo), lane_step[0]);
    auto edge1 = hn::Add(hn::Set(di, row.start[1] + e.dx[1] * rx_lo), lane_step[1]);
    auto edge2 = hn::Add(hn::Set(di, row.start[2] + e.dx[2] * rx_lo), lane_step[2]);
    if (x_hi - x_lo < lanes) {
      // A span of one vector (a sliver's row: most rows of a dense mesh's shadow volume quads)
      // without a branch on what it holds: whether a sliver's row covers a pixel and passes the
      // depth test follows no pattern a branch predictor learns, and masked loads and stores of
      // an empty mask touch nothing. Longer spans skip the vectors with nothing to draw (a big
      // volume polygon's: every span branch-free was slower, bench/README.md).
      StencilVector<kRule, kOwned, false>(e, contribution, target, owners, y, x_lo,
                                          size_t(x_hi - x_lo + 1), edge0, edge1, edge2,
                                          row_depth, covered, writes);
      continue;
    }
    for (int x = x_lo; x <= x_hi; x += lanes, edge0 = hn::Add(edge0, vector_step[0]),
             edge1 = hn::Add(edge1, vector_step[1]), edge2 = hn::Add(edge2, vector_step[2]))
      StencilVector<kRule, kOwned, true>(e, contribution, target, owners, y, x,
                                         size_t(x_hi - x + 1), edge0, edge1, edge2, row_depth,
                                         covered, writes);
  }
  counts.covered += covered;
  counts.writes += writes;
}

void StencilKernelSimd(const TileEdges& e, int32_t contribution, DepthRule rule,
                       const StencilTarget& target, KernelCounts& counts,
                       StencilOwners owners) {
  const bool owned = owners.any();
  if (rule == DepthRule::Closer) {
    if (owned) return StencilRows<DepthRule::Closer, true>(e, contribution, target, counts, owners);
    return StencilRows<DepthRule::Closer, false>(e, contribution, target, counts, owners);
  }
  if (owned) return StencilRows<DepthRule::NotCloser, true>(e, contribution, target, counts, owners);
  StencilRows<DepthRule::NotCloser, false>(e, contribution, target, counts, owners);
}

void RowSpansSimd(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi) {
  SpansOfRows(RowSpans(e), y0, count, x_lo, x_hi);
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(DepthKernelSimd);
HWY_EXPORT(StencilKernelSimd);
HWY_EXPORT(RowSpansSimd);

void rowSpans(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(RowSpansSimd)(e, y0, count, x_lo, x_hi);
  } else {
    rowSpansScalar(e, y0, count, x_lo, x_hi);
  }
}

void depthKernel(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                 KernelCounts& counts, bool simd) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(DepthKernelSimd)(e, primitive, target, counts);
  } else {
    depthKernelScalar(e, primitive, target, counts);
  }
}

void stencilKernel(const TileEdges& e, int32_t contribution, DepthRule rule,
                   const StencilTarget& target, KernelCounts& counts, bool simd,
                   StencilOwners owners) {
  if (useSimd(simd)) {
    HWY_DYNAMIC_DISPATCH(StencilKernelSimd)(e, contribution, rule, target, counts, owners);
  } else {
    stencilKernelScalar(e, contribution, rule, target, counts, owners);
  }
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void depthKernel(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                 KernelCounts& counts, bool) {
  depthKernelScalar(e, primitive, target, counts);
}

void stencilKernel(const TileEdges& e, int32_t contribution, DepthRule rule,
                   const StencilTarget& target, KernelCounts& counts, bool,
                   StencilOwners owners) {
  stencilKernelScalar(e, contribution, rule, target, counts, owners);
}

void rowSpans(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi, bool) {
  rowSpansScalar(e, y0, count, x_lo, x_hi);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
