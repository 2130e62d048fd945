#include "shadows/exact/edge_screen_test.h"

#include <algorithm>

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
      const float qx = block.qx[i], qy = block.qy[i], qz = block.qz[i];
      auto depth = [&](const float* v) { return (v[0] * qx + v[1] * qy) + v[2] * qz; };
      for (int k = 0; k < t.triangle_count; ++k) {
        const float* p = t.triangle[k];
        const float e = ((p[0] * sx + p[1] * sy) + p[2] * z) + p[3];
        const bool positive = e > t.triangle_margin[k];
        const bool negative = e < -t.triangle_margin[k];
        unknown |= !positive && !negative;
        if (t.cuts[k]) {
          // No proof without q: the pixel is kept.
          const bool in_front =
              block.has_q &&
              (std::max(std::max(depth(t.ends[0]), depth(t.ends[1])), depth(t.opposite[k])) +
               block.reach[i]) + block.slack[i] * t.cut_extent[k] < 0.0f;
          unknown |= !in_front;
          if (positive) weight += t.weight[k];
          if (negative) weight -= t.weight[k];
        } else if (t.light_above[k] ? negative : positive) {
          weight += t.weight[k];
        }
      }
      keep = unknown || weight != 0;
    }
    if (keep) out |= uint64_t(1) << i;
  }
  return out;
}

}  // namespace penumbra
