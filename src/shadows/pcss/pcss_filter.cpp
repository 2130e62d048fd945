#include "shadows/pcss/pcss_filter.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace penumbra {

std::vector<double> nearestOccluders(const LightDepthMaps& maps) {
  std::vector<double> nearest;
  for (const Image<float>& depth : maps.depth) {
    // Reversed-Z: the largest stored depth is the nearest occluder. Rows in parallel, then the
    // largest of the rows' (a maximum: the same whatever the order).
    std::vector<float> rows(size_t(depth.height()), 0.0f);
    parallelFor(rows.size(), [&](size_t y) {
      const float* row = depth.row(int(y));
      float largest = 0.0f;
      for (int x = 0; x < depth.width(); ++x) largest = std::max(largest, row[x]);
      rows[y] = largest;
    });
    const float largest = rows.empty() ? 0.0f : *std::max_element(rows.begin(), rows.end());
    nearest.push_back(largest > 0.0f ? maps.near / double(largest) : INFINITY);
  }
  return nearest;
}

double aboveHorizon(double height, double radius) {
  if (!(radius > 0.0)) return 1.0;
  const double t = std::clamp(height / radius, -1.0, 1.0);
  // The area of the disk's part beyond a chord t radii from its centre, over the disk's.
  return 0.5 + (t * std::sqrt(1.0 - t * t) + std::asin(t)) / 3.141592653589793;
}

double pixelRotation(int x, int y) {
  uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return double(h >> 8) / double(1u << 24);
}

}  // namespace penumbra
