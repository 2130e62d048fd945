#pragma once
// Helpers for rasterizer tests: triangles placed directly in screen space.
#include <cstdint>
#include <random>

#include "core/math.h"
#include "raster/triangle_setup.h"

namespace penumbra::testing {

// Clip coordinates (w = 1) of screen position (sx, sy) in pixels with reversed-Z depth d.
inline vec4 screenToClip(double sx, double sy, double d, int width, int height) {
  return vec4(float(2.0 * sx / width - 1.0), float(1.0 - 2.0 * sy / height), float(d), 1.0f);
}

// Deterministic uniform numbers for test geometry (std distributions differ across libraries).
class TestRandom {
 public:
  explicit TestRandom(uint64_t seed) : state_(seed * 6364136223846793005ull + 1442695040888963407ull) {}
  double uniform() {  // [0, 1)
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return double(state_ >> 11) * (1.0 / 9007199254740992.0);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  uint64_t state_;
};

}  // namespace penumbra::testing
