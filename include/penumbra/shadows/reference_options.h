#pragma once
// Options of the ray-traced oracle (`reference`). For typed access to a technique's options:
//   config.options<penumbra::ReferenceOptions>().rays = 64;
#include <cstdint>

namespace penumbra {

struct ReferenceOptions {
  // Rays per pixel over the spherical light (1..4096); with a point light (radius 0), or when
  // `hard` is set, one ray to the light centre.
  int rays = 256;
  bool hard = false;
  uint64_t seed = 1;  // of the stratified ray directions (light_sampling.h)
};

}  // namespace penumbra
