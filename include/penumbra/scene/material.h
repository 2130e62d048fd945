#pragma once
#include <string>

#include <penumbra/core/math.h>

namespace penumbra {

// Lambert + Blinn-Phong + ambient, the papers' shading (see render/shading.h).
struct Material {
  std::string name = "default";
  vec3 albedo{0.8f};       // diffuse reflectance, linear RGB
  vec3 specular{0.0f};     // specular reflectance
  float shininess = 32.0f; // Blinn-Phong exponent
};

}  // namespace penumbra
