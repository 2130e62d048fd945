// Per-target helper of the pixel kernels (raster/tile_kernels_simd.cpp,
// shadows/wedge/wedge_kernel_simd.cpp, shadows/mask/mask_kernel_simd.cpp): RowSpans::span for
// a run of rows, several rows per SIMD step in double, the same operations lane by lane, so the
// same columns (rowSpans in tile_kernels.h). Shadow volume quads seen nearly edge-on are slivers
// that cover about one pixel per row of their rects, and there finding one row's span after
// another was a large part of a kernel's time. Included once per Highway target (the include
// guard toggles with HWY_TARGET_TOGGLE).
#if defined(PENUMBRA_ROW_SPANS_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef PENUMBRA_ROW_SPANS_SIMD_INL_H_
#undef PENUMBRA_ROW_SPANS_SIMD_INL_H_
#else
#define PENUMBRA_ROW_SPANS_SIMD_INL_H_
#endif

#include <algorithm>
#include <cstdint>

#include <hwy/highway.h>

#include "raster/tile_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// rowSpans (tile_kernels.h), count <= kRowSpanBatch, arrays of kRowSpanArray entries. Per
// lane: the row's edge values at the tile origin's column in int32 as the kernels have them,
// then in double -r / dx rounded outwards, as span() does (with its 1 / dx).
HWY_INLINE void SpansOfRows(const RowSpans& spans, int y0, int count, int32_t* x_lo,
                            int32_t* x_hi) {
  const TileEdges& e = spans.edges();
  const double* inverse_dx = spans.inverseDx();
  const hn::CappedTag<double, 8> dd;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const int lanes = int(hn::Lanes(dd));
  const double first = double(e.x0 - e.tx0), last = double(e.x1 - e.tx0);
  const auto zero = hn::Zero(dd);
  for (int k = 0; k < count; k += lanes) {
    const auto ry = hn::Add(hn::Iota(di, 0), hn::Set(di, y0 + k - e.ty0));
    auto lo = hn::Set(dd, first), hi = hn::Set(dd, last);
    auto empty = hn::Lt(zero, zero);  // all false
    for (int i = 0; i < 3; ++i) {
      // e0 + dy ry in int32, exactly as the row loop computes it, then in double.
      const auto r =
          hn::PromoteTo(dd, hn::Add(hn::Set(di, e.e0[i]), hn::Mul(hn::Set(di, e.dy[i]), ry)));
      if (e.dx[i] == 0) {
        empty = hn::Or(empty, hn::Lt(r, zero));
        continue;
      }
      const auto at = hn::Mul(hn::Neg(r), hn::Set(dd, inverse_dx[i]));  // where the value is 0
      if (e.dx[i] > 0)
        lo = hn::Max(lo, hn::Floor(at));
      else
        hi = hn::Min(hi, hn::Ceil(at));
    }
    // Empty where a dx = 0 edge is negative or the bounds cross (then the marker tx0 + 1 >
    // tx0); lo and hi are clamped into the rect's columns before the conversion to int.
    empty = hn::Or(empty, hn::Not(hn::Le(lo, hi)));
    lo = hn::IfThenElse(empty, hn::Set(dd, 1.0), hn::Min(lo, hn::Set(dd, last)));
    hi = hn::IfThenElse(empty, zero, hn::Max(hi, hn::Set(dd, first)));
    const auto origin = hn::Set(di, e.tx0);
    hn::StoreU(hn::Add(hn::DemoteTo(di, lo), origin), di, x_lo + k);
    hn::StoreU(hn::Add(hn::DemoteTo(di, hi), origin), di, x_hi + k);
  }
}

// A kernel's row loop over [y_lo, y_hi], asking for every row in order: each row's span,
// found kRowSpanBatch rows at a time.
class BatchedRowSpans {
 public:
  BatchedRowSpans(const RowSpans& spans, int y_lo, int y_hi)
      : spans_(spans), y_lo_(y_lo), y_hi_(y_hi) {}
  // Row y's columns [x_lo, x_hi]; false when span() finds none.
  bool at(int y, int& x_lo, int& x_hi) {
    const int k = (y - y_lo_) % kRowSpanBatch;
    if (k == 0) SpansOfRows(spans_, y, std::min(kRowSpanBatch, y_hi_ - y + 1), lo_, hi_);
    x_lo = lo_[k];
    x_hi = hi_[k];
    return x_lo <= x_hi;
  }

 private:
  const RowSpans& spans_;
  int y_lo_, y_hi_;
  int32_t lo_[kRowSpanArray], hi_[kRowSpanArray];
};

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#endif  // include guard
