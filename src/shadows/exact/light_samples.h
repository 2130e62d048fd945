#pragma once
// The fixed light sample set of the exact soft shadow volumes, and which of its blocks an edge's
// sector can reach (exact_technique.cpp).
#include <cstdint>
#include <vector>

#include "shadows/exact/sample_kernel.h"
#include "shadows/stages/light_sampling/light_sampling.h"

namespace penumbra {

// The fixed sample set as polar points of the unit disk (light_sampling.h), sorted by angle,
// padded to whole blocks with points at the centre that are never counted. A sample's angle
// around the light centre on the sample plane is its disk angle at every pixel (only its
// distance from the centre depends on the pixel), so the samples an edge's sector can hold are
// one or two runs of this order: the pass over the samples visits only those blocks.
struct SortedSamples {
  int n = 0;
  size_t padded = 0;
  std::vector<DiskPoint> disk;  // n entries
  // The same samples as points of the unit square (disk and rectangle lights place them there,
  // planarLightPoint) and each one's index in the set fixedSamples gives (the oracle's order).
  std::vector<vec2> square;
  std::vector<uint32_t> order;
  // Per block of kSampleBlock samples, the pseudo-angles of its first and last real sample.
  std::vector<double> block_first, block_last;
  std::vector<float> radius2, cos_phi, sin_phi;  // padded entries
};

// The set of n samples for `seed` (fixedSamples), as the oracle's `--sample-set fixed` takes it.
SortedSamples makeSampleSet(int n, uint64_t seed);

// The blocks of samples whose pseudo-angle may lie in [from, to] (from in [0, 4), to - from
// < 2, the half turn; to may pass 4 and wrap): one or two runs [begin, end) of whole blocks.
struct SampleRuns {
  uint32_t begin[2] = {0, 0}, end[2] = {0, 0};
};
SampleRuns sampleRuns(const SortedSamples& set, double from, double to);

// sampleRuns of count ranges [from[i], to[i]] into out[i]. The SIMD twin (light_samples_simd.cpp)
// counts, for several ranges at once, the blocks below each bound (the search's index: the
// bounds are sorted) over every block of a set of up to kBatchRunBlocks blocks (N = 512), and
// searches range by range for larger sets; the same runs either way.
inline constexpr size_t kBatchRunBlocks = 32;
void sampleRunsBatch(const SortedSamples& set, const double* from, const double* to, int count,
                     SampleRuns* out, bool simd);

}  // namespace penumbra
