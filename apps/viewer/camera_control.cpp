#include "camera_control.h"

#include <algorithm>
#include <cmath>

namespace penumbra::viewer {

namespace {

constexpr float kDegreesPerPixel = 0.4f;
constexpr float kMaxTiltDegrees = 85.0f;  // from the horizontal

// World units per pixel for a point `distance` in front of the camera.
float worldPerPixel(const Camera& camera, float distance, int frame_height) {
  const float half = std::tan(glm::radians(camera.fov_y) * 0.5f);
  return 2.0f * distance * half / float(std::max(frame_height, 1));
}

vec3 cameraRight(const Camera& camera) {
  const vec3 forward = glm::normalize(camera.target - camera.position);
  return glm::normalize(glm::cross(forward, camera.up));
}

}  // namespace

void orbitCamera(Camera& camera, float dx, float dy) {
  const vec3 up = glm::normalize(camera.up);
  const vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  if (distance <= 0.0f) return;
  const vec3 dir = offset / distance;
  // Spherical angles of the eye about the target, with `up` as the pole.
  const float height = std::clamp(glm::dot(dir, up), -1.0f, 1.0f);
  float tilt = glm::degrees(std::asin(height));
  vec3 flat = dir - up * height;
  if (glm::length(flat) < 1e-6f) flat = glm::normalize(glm::cross(up, vec3(1.0f, 0.0f, 0.0f)));
  flat = glm::normalize(flat);
  const vec3 side = glm::normalize(glm::cross(up, flat));
  const float yaw = glm::radians(-dx * kDegreesPerPixel);
  const vec3 turned = std::cos(yaw) * flat + std::sin(yaw) * side;
  tilt = std::clamp(tilt + dy * kDegreesPerPixel, -kMaxTiltDegrees, kMaxTiltDegrees);
  const float t = glm::radians(tilt);
  camera.position = camera.target + distance * (std::cos(t) * turned + std::sin(t) * up);
}

void panCamera(Camera& camera, float dx, float dy, int frame_height) {
  const float distance = glm::length(camera.target - camera.position);
  const float scale = worldPerPixel(camera, distance, frame_height);
  const vec3 right = cameraRight(camera);
  const vec3 up = glm::normalize(glm::cross(right, glm::normalize(camera.target - camera.position)));
  // Dragging right moves the scene right: the camera goes left.
  const vec3 move = (-dx * right + dy * up) * scale;
  camera.position += move;
  camera.target += move;
}

void zoomCamera(Camera& camera, float steps) {
  const vec3 offset = camera.position - camera.target;
  const float factor = std::pow(0.9f, steps);
  // Never onto the target, where the view direction is undefined.
  const float distance = std::max(glm::length(offset) * factor, 1e-3f);
  camera.position = camera.target + glm::normalize(offset) * distance;
}

void dragLight(Light& light, const Camera& camera, float dx, float dy, int frame_height,
               bool vertical) {
  const vec3 to_light = light.center - camera.position;
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const float depth = std::max(glm::dot(to_light, forward), camera.near_plane);
  const float scale = worldPerPixel(camera, depth, frame_height);
  const vec3 up = glm::normalize(camera.up);
  if (vertical) {
    light.center += up * (-dy * scale);
    return;
  }
  const vec3 right = cameraRight(camera);
  vec3 ahead = forward - up * glm::dot(forward, up);
  ahead = glm::length(ahead) > 1e-6f ? glm::normalize(ahead) : glm::normalize(glm::cross(up, right));
  // Mouse up pushes the light away from the camera.
  light.center += (dx * right - dy * ahead) * scale;
}

}  // namespace penumbra::viewer
