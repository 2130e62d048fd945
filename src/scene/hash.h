#pragma once
// Portable deterministic randomness for procedural geometry: integer hashes give the same bits on
// every platform and compiler, which std:: distributions do not promise.
#include <cstdint>

namespace penumbra {

// A 32-bit integer mixer (the "lowbias32" finaliser, bias ~0.17 of the ideal avalanche).
inline uint32_t mixBits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Hash of a seed and two integer coordinates.
inline uint32_t hashCoords(uint32_t seed, uint32_t x, uint32_t y) {
  return mixBits((mixBits(mixBits(seed ^ 0x9e3779b9u) ^ x) + 0x632be5abu) ^ y);
}

// Uniform in [-1, 1): the top 24 bits of the hash, exactly representable in a float.
inline float signedUnit(uint32_t h) {
  return float(h >> 8) * (2.0f / 16777216.0f) - 1.0f;
}

}  // namespace penumbra
