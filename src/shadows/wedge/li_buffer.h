#pragma once
// The light intensity (LI) buffer of the papers (2002 section 4; 2004 section 2): a signed
// 16-bit stencil buffer, cleared to 255 (fully lit); wedges add and subtract, and the result is
// clamped to [0, 255] at the end. Additions wrap around in two's complement like the hardware
// buffer they model, so at most 127 overlapping volumes are representable (2004 section 2);
// wrapping also keeps the sum independent of the order of additions.
#include <cstdint>

#include "core/image.h"
#include "core/stats.h"
#include "shadows/technique.h"

namespace penumbra {

inline constexpr int16_t kLiFull = 255;

using LiBuffer = Image<int16_t>;

inline int16_t liAdd(int16_t li, int32_t value) {
  return int16_t(uint16_t(uint32_t(int32_t(li)) + uint32_t(value)));
}

// Visibility in [0, 1] of a pixel with a surface = clamp(LI, 0, full) / full (the background
// is 1: resolveVisibility, facing_away.h). `hard`: the light has no radius, so the buffer holds
// full - full * count of the hard shadow volume; visibility is then 1 only where the count is
// 0, the ShadowVolume rule. A count below 0 (a rasterization tie on a shadow boundary; the eye
// inside a volume with z-pass) is shadow there too, where clamping would make it lit: radius 0
// must give the hard image exactly.
inline float liVisibility(int16_t li, int full, bool hard) {
  if (hard) return li == full ? 1.0f : 0.0f;
  return float(li < 0 ? 0 : (li > full ? full : li)) / float(full);
}

// The wedge passes of a wedge technique (wedge_technique.h) up to the LI buffer, before it is
// clamped into visibility: implementations are compared on it (the three-pass and single-pass
// buffers are equal value for value, values outside [0, full] included).
struct WedgeLi {
  LiBuffer li;
  int full = kLiFull;  // LI of a fully visible light
  Stats stats;
  // Asked for by RenderContext::debug_layers (shadows/technique.h), on the main pass only.
  std::vector<DebugLayer> debug_layers;
};

}  // namespace penumbra
