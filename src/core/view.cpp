#include "core/view.h"

#include <cmath>

#include "core/error.h"

namespace penumbra {

View View::lookAt(int width, int height, vec3 eye, vec3 target, vec3 up, float fov_y_degrees,
                  float near_plane) {
  PENUMBRA_CHECK(width > 0 && height > 0, "image size {}x{} must be positive", width, height);
  PENUMBRA_CHECK(width <= 8192 && height <= 8192,
                 "image size {}x{} is larger than the supported 8192x8192", width, height);
  PENUMBRA_CHECK(isFinite(eye) && isFinite(target) && isFinite(up),
                 "camera position, target and up must be finite numbers");
  // Farther out, squared lengths overflow float: the view direction would come out as zero
  // and the camera be called parallel to its up vector.
  constexpr float kMaxCoordinate = 1e18f;
  auto within = [&](const vec3& v) {
    return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
           std::abs(v.z) <= kMaxCoordinate;
  };
  PENUMBRA_CHECK(within(eye) && within(target),
                 "camera position ({}, {}, {}) and target ({}, {}, {}) must lie within {:g} of "
                 "the origin in every coordinate",
                 eye.x, eye.y, eye.z, target.x, target.y, target.z, kMaxCoordinate);
  PENUMBRA_CHECK(glm::length(target - eye) > 0.0f, "camera target equals its position");
  PENUMBRA_CHECK(glm::length(glm::cross(glm::normalize(target - eye), up)) > 1e-6f,
                 "camera up vector is parallel to the view direction");
  PENUMBRA_CHECK(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f,
                 "camera fov {} must be in (0, 180) degrees", fov_y_degrees);
  PENUMBRA_CHECK(near_plane > 0.0f && std::isfinite(near_plane), "camera near plane {} must be > 0",
                 near_plane);

  View v;
  v.width = width;
  v.height = height;
  v.near_plane = near_plane;
  v.eye = eye;
  v.view = glm::lookAt(eye, target, up);
  const float f = 1.0f / std::tan(glm::radians(fov_y_degrees) * 0.5f);
  const float aspect = float(width) / float(height);
  mat4 p(0.0f);  // column-major: p[column][row]
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[3][2] = near_plane;  // clip.z = near * w_h
  p[2][3] = -1.0f;       // clip.w = -z_view
  v.projection = p;
  v.view_projection = p * v.view;
  v.inverse_view = glm::inverse(v.view);
  return v;
}

dvec3 View::unprojectScreen(double sx, double sy, double depth) const {
  const double w = double(near_plane) / depth;  // distance along -z in view space
  const double ndc_x = 2.0 * sx / width - 1.0;
  const double ndc_y = 1.0 - 2.0 * sy / height;
  const dvec4 p_view(ndc_x * w / double(projection[0][0]), ndc_y * w / double(projection[1][1]),
                     -w, 1.0);
  return dvec3(dmat4(inverse_view) * p_view);
}

dvec3 View::unproject(int x, int y, float depth) const {
  return unprojectScreen(x + 0.5, y + 0.5, double(depth));
}

}  // namespace penumbra
