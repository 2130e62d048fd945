#pragma once
// Instances: one mesh, a prototype held once in its own object space, placed many times with a
// transform each (a city's buildings, trees and lamps; docs/scene-format.md, "instances").
#include <cstdint>
#include <string>

#include <penumbra/core/math.h>

namespace penumbra {

struct MeshInstance {
  uint32_t prototype = 0;  // index into Scene::prototypes
  mat4 transform{1.0f};    // object space to world space (affine, non-singular)
  uint32_t material = 0;   // index into Scene::materials
  std::string name;        // for messages; empty: "<prototype name> #<instance index>"
};

}  // namespace penumbra
