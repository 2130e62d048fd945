#pragma once
// The shadow mask's 8-bit arithmetic (Roettger, Irion and Ertl 2002, sections 4.2 to 4.4) and
// what its passes cost (Table 1).
//
// Numeric convention: a mask value is an unsigned 8-bit channel read as v / 255, as an RGBA8
// frame buffer holds it. The blends the paper uses instead of increment and decrement are
//   double: glBlendFunc(GL_DST_COLOR, GL_ONE), src 1:   v -> min(2 v, 255)  (the colour clamp)
//   halve:  glBlendFunc(GL_DST_COLOR, GL_ZERO), src 1/2: v -> ceil(v / 2)   (halves round up)
// Rounding halves up (the nearest representable value, ties up) makes 255 behave as 256 under
// halving, so 2^-k for k = 0..8 are exactly 255, 128, 64, ..., 2, 1: the mask only ever holds
// these nine values, and a halving of 1 leaves 1 (2^-8 is the smallest power it can hold).
// k steps at once are one step each in turn: min(v 2^k, 255) and ceil(v / 2^k) (nested
// ceilings of halves are the ceiling of the quotient), which is what the kernels compute.
#include <algorithm>
#include <cstdint>

#include <penumbra/shadows/mask_options.h>

namespace penumbra {

inline constexpr uint32_t kMaskOne = 255;      // 1
inline constexpr uint32_t kMaskHalf = 128;     // 1/2
inline constexpr uint32_t kMaskQuarter = 64;   // 1/4
// Steps of one polygon beyond this change nothing more (255 << 9 still fits, 2^9 > 255).
inline constexpr int kMaskMaxSteps = 9;

inline uint32_t maskDouble(uint32_t v, int k) { return std::min<uint32_t>(v << k, kMaskOne); }
inline uint32_t maskHalve(uint32_t v, int k) { return (v + (1u << k) - 1u) >> k; }
// Whether k halvings of v lose a power of two: v holds 2^-j (j <= 8; 255 acting as 256), and
// 2^-(j+k) is below the smallest value the 8 bits hold (1 = 2^-8) exactly when v < 2^k. The
// pixel's value is then too high by the lost factor: its count is no longer recoverable (the
// mask's only inexact step once the halvings are drawn before the doublings, shadow_mask.cpp).
inline bool maskHalvingLoses(uint32_t v, int k) {
  return (v == kMaskOne ? 256u : v) < (1u << k);
}

// Section 4.2: every pixel starts at 1/4, front faces double, back faces halve (three-pass
// normalisation); section 4.4: it starts at 1, front faces halve, back faces double (max-blend).
inline uint32_t maskInitialValue(MaskNormalisation n) {
  return n == MaskNormalisation::ThreePass ? kMaskQuarter : kMaskOne;
}
// Whether a polygon whose stencil contribution is positive (a front face with z-pass, a back
// face with z-fail) doubles the mask; the negative ones do the opposite.
inline bool maskPositiveDoubles(MaskNormalisation n) { return n == MaskNormalisation::ThreePass; }

// The full-window rectangles of the normalisation, one at a time (Figure 4): after the volumes
// a lit pixel holds 1/4 or less (clamping only ever loses doublings), a shadowed one 1/2 or 1.
inline uint32_t threePassRectangle1(uint32_t v) { return maskDouble(v, 1); }  // *2
inline uint32_t threePassRectangle2(uint32_t v) { return kMaskOne - v; }      // invert
// Black or ambient shadows: *2 again, lit 254 or 255 (a lit pixel at 1/4 ends at 254/255, one
// below it at 255), shadowed 0. Attenuated by 1/2: glBlendFunc(GL_ONE, GL_ONE) with brightness
// 1/2 adds 128: lit 255, shadowed 128.
inline uint32_t threePassRectangle3(uint32_t v, MaskShadowMode mode) {
  return mode == MaskShadowMode::Attenuated ? std::min<uint32_t>(v + kMaskHalf, kMaskOne)
                                            : maskDouble(v, 1);
}
// Figure 5: glBlendEquation(GL_MAX) with brightness 1/2: lit 255, shadowed 128.
inline uint32_t maxBlendRectangle(uint32_t v) { return std::max(v, kMaskHalf); }

// The normalised mask says lit above 1/2 in every mode: lit pixels end at 254 or 255, shadowed
// ones at 0 or 128 (the attenuation the paper multiplies the frame with).
inline bool maskLit(uint32_t normalised) { return normalised > kMaskHalf; }

// Table 1: rendering passes of the scene (the first draws the depth and, for the alpha buffer,
// the colour too; the screen buffer needs the scene drawn again to multiply it with the mask,
// ambient shadows once more to add the ambient term) and full-window rectangles (normalisation,
// and for the alpha buffer the final multiply by the destination alpha).
struct MaskPasses {
  int render_passes;
  int rectangles;
};
enum class MaskChannel { Alpha, Colour };
inline MaskPasses maskPasses(MaskChannel channel, MaskNormalisation n, MaskShadowMode mode) {
  const int normalise = n == MaskNormalisation::MaxBlend ? 1 : 3;
  const int ambient = mode == MaskShadowMode::Ambient ? 1 : 0;
  if (channel == MaskChannel::Alpha) return {1 + ambient, normalise + 1};
  return {2 + ambient, normalise};
}

}  // namespace penumbra
