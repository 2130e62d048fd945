#pragma once
// Screen-space numeric formats shared by triangle setup and the pixel kernels.
//
// Vertex coordinates are 28.4 fixed point: 16 sub-pixel steps per pixel, snapped with round to
// nearest. Pixel (x, y) is sampled at its centre, (16x + 8, 16y + 8) in these units.
//
// Triangles are clipped to a guard band of kGuardBandPixels around the image, so coordinates
// stay within +-2^14 pixels = +-2^18 units and edge gradients within 2^19 units. Per pixel an
// edge function changes by at most 16 * 2^19 = 2^23, so over one bin tile of 32 x 32 pixels it
// changes by less than 2^29: edge functions that cross a tile fit int32 there (the SIMD lanes),
// while setup and tile tests use int64.
#include <cstdint>

namespace penumbra {

inline constexpr int kSubpixelBits = 4;
inline constexpr int kSubpixelSteps = 1 << kSubpixelBits;  // 16
inline constexpr int kGuardBandPixels = 4096;
inline constexpr int kMaxImageSize = 8192;  // kMaxImageSize + kGuardBandPixels < 2^14

// Bin tiles: the unit of work a thread owns.
inline constexpr int kBinTileLevel = 5;
inline constexpr int kBinTileSize = 1 << kBinTileLevel;  // 32 pixels

inline constexpr int64_t pixelCentre(int pixel) {
  return int64_t(pixel) * kSubpixelSteps + kSubpixelSteps / 2;
}

// floor(a / b) and ceil(a / b) for b > 0 (C++ division truncates toward zero).
inline constexpr int64_t floorDiv(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
inline constexpr int64_t ceilDiv(int64_t a, int64_t b) {
  return a >= 0 ? (a + b - 1) / b : -((-a) / b);
}

// The first pixel whose centre lies at or after `units` (28.4), and the last whose centre lies
// at or before it.
inline constexpr int64_t firstPixelFrom(int64_t units) {
  return ceilDiv(units - kSubpixelSteps / 2, kSubpixelSteps);
}
inline constexpr int64_t lastPixelTo(int64_t units) {
  return floorDiv(units - kSubpixelSteps / 2, kSubpixelSteps);
}

}  // namespace penumbra
