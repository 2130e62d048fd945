#pragma once
#include <penumbra/core/math.h>

namespace penumbra {

// A spherical light (the papers' light for penumbra wedges). radius 0 is a point light and
// every technique must then give exactly the hard-shadow result.
struct Light {
  vec3 center{0.0f, 10.0f, 0.0f};
  float radius = 0.0f;      // world units, >= 0
  vec3 color{1.0f};         // linear RGB
  float intensity = 1.0f;   // scales color; no distance falloff (as in the papers' images)
};

}  // namespace penumbra
