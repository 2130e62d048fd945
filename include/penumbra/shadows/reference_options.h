#pragma once
// Options of the ray-traced oracle (`reference`). For typed access to a technique's options:
//   config.options<penumbra::ReferenceOptions>().rays = 64;
#include <cstdint>

namespace penumbra {

// Which light samples a pixel's rays go to (light_sampling.h): a stratified set jittered
// afresh for every pixel (noise), or one stratified set shared by every pixel (the set the exact
// soft shadow volumes count, so the two can be compared sample for sample).
enum class SampleSet { PerPixel, Fixed };

struct ReferenceOptions {
  // Rays per pixel over the spherical light (1..4096); with a point light (radius 0), or when
  // `hard` is set, one ray to the light centre.
  int rays = 256;
  bool hard = false;
  uint64_t seed = 1;  // of the stratified ray directions (light_sampling.h)
  SampleSet samples = SampleSet::PerPixel;
};

}  // namespace penumbra
