#pragma once
// The light intensity (LI) buffer of the papers (2002 section 4; 2004 section 2): a signed
// 16-bit stencil buffer, cleared to 255 (fully lit); wedges add and subtract, and the result is
// clamped to [0, 255] at the end. Additions wrap around in two's complement like the hardware
// buffer they model, so at most 127 overlapping volumes are representable (2004 section 2);
// wrapping also keeps the sum independent of the order of additions.
#include <cstdint>

#include "core/image.h"

namespace penumbra {

inline constexpr int16_t kLiFull = 255;

using LiBuffer = Image<int16_t>;

inline int16_t liAdd(int16_t li, int32_t value) {
  return int16_t(uint16_t(uint32_t(int32_t(li)) + uint32_t(value)));
}

// Visibility in [0, 1] = clamp(LI, 0, full) / full; background pixels (depth 0) are 1.
Image<float> liToVisibility(const LiBuffer& li, const Image<float>& depth, int full = kLiFull);

}  // namespace penumbra
