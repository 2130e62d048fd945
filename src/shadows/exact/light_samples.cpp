#include "shadows/exact/light_samples.h"

#include <algorithm>

#include "core/pseudo_angle.h"

namespace penumbra {

SortedSamples makeSampleSet(int n, uint64_t seed) {
  SortedSamples set;
  set.n = n;
  set.padded = (size_t(n) + kSampleBlock - 1) / kSampleBlock * kSampleBlock;
  std::vector<vec2> square(static_cast<size_t>(n));
  fixedSamples(n, seed, square.data());
  std::vector<DiskPoint> disk;
  for (int i = 0; i < n; ++i) disk.push_back(concentricDisk(square[size_t(i)]));
  auto angle = [](const DiskPoint& d) { return pseudoAngle(d.cos_phi, d.sin_phi); };
  for (int i = 0; i < n; ++i) set.order.push_back(uint32_t(i));
  std::stable_sort(set.order.begin(), set.order.end(), [&](uint32_t a, uint32_t b) {
    return angle(disk[a]) < angle(disk[b]);
  });
  for (const uint32_t i : set.order) {
    set.disk.push_back(disk[i]);
    set.square.push_back(square[i]);
  }
  set.radius2.assign(set.padded, 0.0f);
  set.cos_phi.assign(set.padded, 1.0f);
  set.sin_phi.assign(set.padded, 0.0f);
  for (int i = 0; i < n; ++i) {
    const DiskPoint& d = set.disk[size_t(i)];
    set.radius2[size_t(i)] = d.radius * d.radius;
    set.cos_phi[size_t(i)] = d.cos_phi;
    set.sin_phi[size_t(i)] = d.sin_phi;
  }
  for (size_t b = 0; b < set.padded; b += kSampleBlock) {
    set.block_first.push_back(angle(set.disk[b]));
    set.block_last.push_back(angle(set.disk[std::min(size_t(n), b + kSampleBlock) - 1]));
  }
  return set;
}

namespace {

// How many of the ascending values are < v (strict) or <= v (!strict): std::lower_bound's and
// std::upper_bound's index, without their branches. An edge's sector lies anywhere around the
// light, so each halving step of those goes either way at random and was mispredicted; here
// the steps depend on the array's size alone and the choice is a conditional move.
size_t countBelow(const std::vector<double>& values, double v, bool strict) {
  const double* base = values.data();
  size_t n = values.size();
  if (n == 0) return 0;
  while (n > 1) {
    const size_t half = n / 2;
    const double probe = base[half - 1];
    base = (strict ? probe < v : probe <= v) ? base + half : base;
    n -= half;
  }
  return size_t(base - values.data()) + ((strict ? *base < v : *base <= v) ? 1 : 0);
}

}  // namespace

SampleRuns sampleRuns(const SortedSamples& set, double from, double to) {
  // Far wider than the float error of the kernel's sector lines (some 1e-7 relative); the
  // pseudo-angle grows at least half as fast as the angle.
  constexpr double kSlack = 1e-5;
  from -= kSlack;
  to += kSlack;
  // Blocks [first block whose last sample >= lo, first block whose first sample > hi).
  auto run = [&](double lo, double hi, uint32_t& begin, uint32_t& end) {
    const size_t b = countBelow(set.block_last, lo, true);     // std::lower_bound
    const size_t e = countBelow(set.block_first, hi, false);   // std::upper_bound
    begin = uint32_t(b * kSampleBlock);
    end = uint32_t(std::max(b, e) * kSampleBlock);
  };
  SampleRuns runs;
  if (from < 0.0) {
    run(0.0, to, runs.begin[0], runs.end[0]);
    run(from + 4.0, 4.0, runs.begin[1], runs.end[1]);
  } else if (to >= 4.0) {
    run(from, 4.0, runs.begin[0], runs.end[0]);
    run(0.0, to - 4.0, runs.begin[1], runs.end[1]);
  } else {
    run(from, to, runs.begin[0], runs.end[0]);
  }
  return runs;
}

}  // namespace penumbra
