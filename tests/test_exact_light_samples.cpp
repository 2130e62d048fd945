// sampleRuns says which blocks of the angle-sorted light samples an edge's sector can reach: the
// exact soft shadow volumes visit only those. A sample of the sector left out of every run would
// keep its count and be lit (or shadowed) where the oracle's ray to it is blocked (or not).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/pseudo_angle.h"
#include "shadows/exact/light_samples.h"

namespace penumbra {
namespace test_exact_light_samples {

// The runs by their definition, scanning every block: from the first block whose last angle
// is >= lo to the first whose first angle is > hi (at least empty), for [from, to] widened by
// sampleRuns' slack and split where it wraps past 0 or 4.
SampleRuns referenceRuns(const SortedSamples& set, double from, double to) {
  const double lo = from - 1e-5, hi = to + 1e-5;
  const size_t blocks = set.block_first.size();
  auto run = [&](double a, double b, uint32_t& begin, uint32_t& end) {
    size_t first = blocks, past = blocks;
    for (size_t k = blocks; k-- > 0;) {
      if (set.block_last[k] >= a) first = k;
      if (set.block_first[k] > b) past = k;
    }
    begin = uint32_t(first * kSampleBlock);
    end = uint32_t(std::max(first, past) * kSampleBlock);
  };
  SampleRuns runs;
  if (lo < 0.0) {
    run(0.0, hi, runs.begin[0], runs.end[0]);
    run(lo + 4.0, 4.0, runs.begin[1], runs.end[1]);
  } else if (hi >= 4.0) {
    run(lo, 4.0, runs.begin[0], runs.end[0]);
    run(0.0, hi - 4.0, runs.begin[1], runs.end[1]);
  } else {
    run(lo, hi, runs.begin[0], runs.end[0]);
  }
  return runs;
}

// Sample sets of 1 to 4096 samples (one block, partial blocks, many blocks) and sectors of every
// width, wrapping past 0 and 4, some starting on a sample's angle and some whose slackened ends
// fall exactly on a block's first or last angle: the runs are the searches' and hold every
// sample of the sector, and the batched form (SIMD over the ranges) gives the same runs.
TEST(ExactLightSamples, RunsHoldEverySampleOfTheSector) {
  std::mt19937_64 random(77);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * (double(random() >> 11) * 0x1.0p-53);
  };
  for (const int n : {1, 7, 16, 17, 100, 256, 512, 1000, 4096}) {
    const SortedSamples set = makeSampleSet(n, uint64_t(n));
    // The batched form (sampleRunsBatch: counted lane by lane for up to kBatchRunBlocks blocks),
    // over batches of 1 to 11 of the trials' ranges.
    std::vector<double> batch_from, batch_to;
    std::vector<SampleRuns> batch_expected;
    auto checkBatch = [&] {
      std::vector<SampleRuns> got(batch_from.size());
      sampleRunsBatch(set, batch_from.data(), batch_to.data(), int(batch_from.size()),
                      got.data(), true);
      for (size_t i = 0; i < got.size(); ++i)
        for (int k = 0; k < 2; ++k) {
          ASSERT_EQ(got[i].begin[k], batch_expected[i].begin[k]) << "n " << n << " batch " << i;
          ASSERT_EQ(got[i].end[k], batch_expected[i].end[k]) << "n " << n << " batch " << i;
        }
      batch_from.clear();
      batch_to.clear();
      batch_expected.clear();
    };
    for (int trial = 0; trial < 400; ++trial) {
      double from = uniform(0.0, 4.0);
      if (trial % 5 == 0) {  // starting on a sample's angle
        const DiskPoint& d = set.disk[size_t(random() % size_t(n))];
        from = pseudoAngle(d.cos_phi, d.sin_phi);
      }
      double to = from + uniform(0.0, 2.0) * (trial % 3 == 0 ? 0.01 : 1.0);
      // Ends on a block's bound after the slack (the searches' ties: < against <=).
      if (trial % 7 == 1) {
        const double bound = set.block_last[random() % set.block_last.size()];
        if ((bound + 1e-5) - 1e-5 == bound) from = bound + 1e-5, to = from + uniform(0.0, 1.0);
      } else if (trial % 7 == 2) {
        const double bound = set.block_first[random() % set.block_first.size()];
        if ((bound - 1e-5) + 1e-5 == bound && bound - 1e-5 >= 0.0)
          to = bound - 1e-5, from = std::max(0.0, to - uniform(0.0, 1.0));
      } else if (trial % 7 == 3) {  // wrapping past 4, the wrapped end on a block's first
        const double bound = set.block_first[random() % set.block_first.size()];
        const double end = bound + 4.0 - 1e-5;
        if ((end + 1e-5) - 4.0 == bound && bound < 0.9)
          to = end, from = 4.0 - uniform(0.01, 1.0);
      }
      const SampleRuns runs = sampleRuns(set, from, to);
      const SampleRuns expected = referenceRuns(set, from, to);
      batch_from.push_back(from);
      batch_to.push_back(to);
      batch_expected.push_back(expected);
      if (int(batch_from.size()) == 1 + trial % 11) checkBatch();
      for (int k = 0; k < 2; ++k) {
        ASSERT_EQ(runs.begin[k], expected.begin[k]) << "n " << n << " [" << from << ", " << to
                                                    << "]";
        ASSERT_EQ(runs.end[k], expected.end[k]) << "n " << n << " [" << from << ", " << to << "]";
      }
      for (int i = 0; i < n; ++i) {
        const DiskPoint& d = set.disk[size_t(i)];
        const double angle = pseudoAngle(d.cos_phi, d.sin_phi);
        const bool inside =
            (angle >= from && angle <= to) || (angle + 4.0 >= from && angle + 4.0 <= to);
        if (!inside) continue;
        const bool visited = (uint32_t(i) >= runs.begin[0] && uint32_t(i) < runs.end[0]) ||
                             (uint32_t(i) >= runs.begin[1] && uint32_t(i) < runs.end[1]);
        ASSERT_TRUE(visited) << "n " << n << " sample " << i << " at " << angle << " in ["
                             << from << ", " << to << "]";
      }
    }
    if (!batch_from.empty()) checkBatch();
  }
}

}  // namespace test_exact_light_samples
}  // namespace penumbra
