#include "shadows/exact/edge_screen_test.h"

namespace penumbra {

uint64_t edgeCandidatesScalar(const EdgeScreenTest& t, const PixelBlock& block) {
  uint64_t out = 0;
  for (int i = 0; i < kBlockPixels; ++i) {
    if (!((block.active >> i) & 1u)) continue;
    const float sx = block.sx[i], sy = block.sy[i], z = block.z[i];
    bool keep = true;
    for (int k = 0; k < t.region_count && keep; ++k) {
      const float* p = t.region[k];
      keep = ((p[0] * sx + p[1] * sy) + p[2] * z) + p[3] >= -t.region_margin[k];
    }
    if (!keep) continue;
    if (t.triangle_count > 0) {
      bool unknown = false;
      int32_t weight = 0;
      for (int k = 0; k < t.triangle_count; ++k) {
        const float* p = t.triangle[k];
        const float e = ((p[0] * sx + p[1] * sy) + p[2] * z) + p[3];
        const bool positive = e > t.triangle_margin[k];
        const bool negative = e < -t.triangle_margin[k];
        unknown |= !positive && !negative;
        if (t.light_above[k] ? negative : positive) weight += t.weight[k];
      }
      keep = unknown || weight != 0;
    }
    if (keep) out |= uint64_t(1) << i;
  }
  return out;
}

}  // namespace penumbra
