// SIMD twin of sampleRuns for several ranges at once (light_samples.h: sampleRunsBatch), a
// range per lane, in double (Highway, dispatched at run time). A bound's block index is the
// number of blocks below it (std::lower_bound's and upper_bound's index on the sorted bounds),
// counted over every block: no branch on where a range lies, at a cost linear in the blocks,
// so only sets of up to kBatchRunBlocks blocks are counted and larger ones searched.
#include "shadows/exact/light_samples.h"

#include <algorithm>

#include "core/simd_dispatch.h"

#ifndef PENUMBRA_SCALAR_ONLY

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shadows/exact/light_samples_simd.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace penumbra {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SampleRunsBatchSimd(const SortedSamples& set, const double* from, const double* to,
                         int count, SampleRuns* out) {
  const hn::CappedTag<double, 8> d;
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
  const auto slack = hn::Set(d, 1e-5);  // sampleRuns' kSlack
  const size_t blocks = set.block_first.size();
  for (size_t base = 0; base < size_t(count); base += lanes) {
    const size_t n = std::min(lanes, size_t(count) - base);
    const auto in = hn::FirstN(d, n);
    const auto lo = hn::Sub(hn::MaskedLoad(in, d, from + base), slack);
    const auto hi = hn::Add(hn::MaskedLoad(in, d, to + base), slack);
    // As sampleRuns: below 0, runs [0, hi] and [lo + 4, 4]; at or past 4, [lo, 4] and
    // [0, hi - 4]; else [lo, hi] alone.
    const auto below_zero = hn::Lt(lo, zero);
    const auto past_four = hn::AndNot(below_zero, hn::Ge(hi, four));
    const auto two_runs = hn::Or(below_zero, past_four);
    const auto lo0 = hn::IfThenElse(below_zero, zero, lo);
    const auto hi0 = hn::IfThenElse(past_four, four, hi);
    const auto lo1 = hn::IfThenElse(below_zero, hn::Add(lo, four), zero);
    const auto hi1 = hn::IfThenElse(below_zero, four, hn::Sub(hi, four));
    auto b0 = zero, e0 = zero, b1 = zero, e1 = zero;
    for (size_t k = 0; k < blocks; ++k) {
      const auto last = hn::Set(d, set.block_last[k]), first = hn::Set(d, set.block_first[k]);
      b0 = hn::Add(b0, hn::IfThenElseZero(hn::Lt(last, lo0), one));
      e0 = hn::Add(e0, hn::IfThenElseZero(hn::Le(first, hi0), one));
      b1 = hn::Add(b1, hn::IfThenElseZero(hn::Lt(last, lo1), one));
      e1 = hn::Add(e1, hn::IfThenElseZero(hn::Le(first, hi1), one));
    }
    HWY_ALIGN double v[4][8];
    hn::Store(b0, d, v[0]);
    hn::Store(hn::Max(b0, e0), d, v[1]);
    hn::Store(hn::IfThenElseZero(two_runs, b1), d, v[2]);
    hn::Store(hn::IfThenElseZero(two_runs, hn::Max(b1, e1)), d, v[3]);
    for (size_t k = 0; k < n; ++k) {
      SampleRuns& runs = out[base + k];
      runs.begin[0] = uint32_t(v[0][k]) * uint32_t(kSampleBlock);
      runs.end[0] = uint32_t(v[1][k]) * uint32_t(kSampleBlock);
      runs.begin[1] = uint32_t(v[2][k]) * uint32_t(kSampleBlock);
      runs.end[1] = uint32_t(v[3][k]) * uint32_t(kSampleBlock);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace penumbra
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace penumbra {

HWY_EXPORT(SampleRunsBatchSimd);

void sampleRunsBatch(const SortedSamples& set, const double* from, const double* to, int count,
                     SampleRuns* out, bool simd) {
  if (useSimd(simd) && set.block_first.size() <= kBatchRunBlocks) {
    HWY_DYNAMIC_DISPATCH(SampleRunsBatchSimd)(set, from, to, count, out);
    return;
  }
  for (int i = 0; i < count; ++i) out[i] = sampleRuns(set, from[i], to[i]);
}

}  // namespace penumbra
#endif  // HWY_ONCE

#else  // PENUMBRA_SCALAR_ONLY

namespace penumbra {

void sampleRunsBatch(const SortedSamples& set, const double* from, const double* to, int count,
                     SampleRuns* out, bool) {
  for (int i = 0; i < count; ++i) out[i] = sampleRuns(set, from[i], to[i]);
}

}  // namespace penumbra

#endif  // PENUMBRA_SCALAR_ONLY
