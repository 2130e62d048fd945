#include "shadows/stages/potential_edges/edge_screen_test.h"

#include <algorithm>

namespace penumbra {

uint64_t edgeCandidatesScalar(const EdgeScreenTest& t, const PixelBlock& block) {
  uint64_t out = 0;
  for (int i = 0; i < kBlockPixels; ++i) {
    if (!((block.active >> i) & 1u)) continue;
    const float sx = block.sx[i], sy = block.sy[i], z = block.z[i], offset = block.offset[i];
    bool keep = true;
    for (int k = 0; k < t.region_count && keep; ++k) {
      const float* p = t.region[k];
      keep = ((p[0] * sx + p[1] * sy) + p[2] * z) + p[3] >= -(t.region_margin[k] + offset);
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
        const float margin = t.triangle_margin[k] + offset;
        const bool positive = e > margin;
        const bool negative = e < -margin;
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

int edgeTileCandidatesScalar(const EdgeScreenTest& t, const EdgeTileBox& box, uint32_t* kept,
                             int& tested) {
  int count = 0;
  tested = 0;
  const float last_centre = float(box.width) - 0.5f;
  for (int ty = box.ty0; ty <= box.ty1; ++ty) {
    const float y0 = float(ty * box.size) + 0.5f;
    const float y1 = float(std::min(ty * box.size + box.size, box.height)) - 0.5f;
    const size_t row = size_t(ty) * size_t(box.columns);
    for (int tx = box.tx0; tx <= box.tx1; ++tx) {
      const float zmin = box.zmin[row + size_t(tx)], zmax = box.zmax[row + size_t(tx)];
      if (!(zmax > 0.0f)) continue;
      ++tested;
      const float x0 = float(tx * box.size) + 0.5f;
      const float x1 = std::min(x0 + float(box.size - 1), last_centre);
      // ((a x + b y) + c z) + d at the corner where it is largest (`high`) or smallest, over
      // depths [lo, hi].
      auto atDepths = [&](const float* p, bool high, float lo, float hi) {
        const float x = (p[0] >= 0.0f) == high ? x1 : x0;
        const float y = (p[1] >= 0.0f) == high ? y1 : y0;
        const float z = (p[2] >= 0.0f) == high ? hi : lo;
        return ((p[0] * x + p[1] * y) + p[2] * z) + p[3];
      };
      auto at = [&](const float* p, bool high) { return atDepths(p, high, zmin, zmax); };
      auto regionMeets = [&](float lo, float hi) {
        for (int k = 0; k < t.region_count; ++k)
          if (!(atDepths(t.region[k], true, lo, hi) >= -(t.region_margin[k] + box.offset)))
            return false;
        return true;
      };
      bool keep;
      if (box.parts != nullptr) {
        // A part that passes implies the whole range passes (its box lies inside it).
        const size_t i = row + size_t(tx);
        const EdgeTileParts& parts = *box.parts;
        keep = (parts.low_zmax[i] > 0.0f && regionMeets(parts.low_zmin[i], parts.low_zmax[i])) ||
               (parts.high_zmax[i] > 0.0f && regionMeets(parts.high_zmin[i], parts.high_zmax[i]));
      } else {
        keep = regionMeets(zmin, zmax);
      }
      if (keep && t.triangle_count > 0 && !t.any_cuts) {
        bool unknown = false;
        int32_t weight = 0;
        for (int k = 0; k < t.triangle_count; ++k) {
          const float margin = t.triangle_margin[k] + box.offset;
          const bool positive = at(t.triangle[k], false) > margin;
          const bool negative = at(t.triangle[k], true) < -margin;
          unknown |= !positive && !negative;
          if (t.light_above[k] ? negative : positive) weight += t.weight[k];
        }
        keep = unknown || weight != 0;
      }
      if (keep) kept[count++] = uint32_t(row) + uint32_t(tx);
    }
  }
  return count;
}

}  // namespace penumbra
