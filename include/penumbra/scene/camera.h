#pragma once
#include <penumbra/core/math.h>
#include <penumbra/core/view.h>

namespace penumbra {

struct Camera {
  vec3 position{0.0f, 2.0f, 8.0f};
  vec3 target{0.0f};
  vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y = 45.0f;       // degrees
  float near_plane = 0.05f;  // world units

  View makeView(int width, int height) const {
    return View::lookAt(width, height, position, target, up, fov_y, near_plane);
  }
};

}  // namespace penumbra
