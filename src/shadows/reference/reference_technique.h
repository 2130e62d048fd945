#pragma once
// The oracle (`reference`): ray-traced visibility with Embree from every pixel's visible point,
// found from the eye pass's depth buffer, so every technique is judged on the same points.
#include <cstdint>

#include "shadows/technique.h"

namespace penumbra {

struct ReferenceOptions {
  // Rays per pixel over the spherical light (1..4096); with a point light (radius 0), or when
  // `hard` is set, one ray to the light centre.
  int rays = 256;
  bool hard = false;
  uint64_t seed = 1;  // of the stratified ray directions (light_sampling.h)
};

TechniqueInfo referenceTechnique();

}  // namespace penumbra
