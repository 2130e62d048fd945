// Orbit, pan, zoom and light drags: what the mouse does to the camera and the lights.
#include <gtest/gtest.h>

#include "camera_control.h"

namespace penumbra::viewer {
namespace test_camera_control {

Camera testCamera() {
  Camera camera;
  camera.position = vec3(0.0f, 2.0f, 8.0f);
  camera.target = vec3(0.0f, 0.5f, 0.0f);
  return camera;
}

// Orbiting turns about the target at a fixed distance; a wrong axis would change the distance
// or move the target.
TEST(CameraControl, OrbitKeepsTargetAndDistance) {
  Camera camera = testCamera();
  const float distance = glm::length(camera.position - camera.target);
  orbitCamera(camera, 100.0f, 30.0f);
  EXPECT_EQ(camera.target, testCamera().target);
  EXPECT_NEAR(glm::length(camera.position - camera.target), distance, 1e-4f);
  EXPECT_GT(glm::length(camera.position - testCamera().position), 1.0f);
  // Far past the pole: still short of it, so "up" never flips.
  orbitCamera(camera, 0.0f, 10000.0f);
  const vec3 dir = glm::normalize(camera.position - camera.target);
  EXPECT_LT(dir.y, 0.999f);
}

TEST(CameraControl, PanMovesCameraAndTargetTogether) {
  Camera camera = testCamera();
  panCamera(camera, 50.0f, 0.0f, 400);
  const vec3 moved = camera.target - testCamera().target;
  EXPECT_EQ(camera.position - testCamera().position, moved);
  EXPECT_LT(moved.x, 0.0f);  // dragging right moves the scene right: the camera goes left
  EXPECT_NEAR(moved.y, 0.0f, 1e-5f);
}

TEST(CameraControl, ZoomApproachesTheTargetNeverReachingIt) {
  Camera camera = testCamera();
  const float distance = glm::length(camera.position - camera.target);
  zoomCamera(camera, 1.0f);
  EXPECT_NEAR(glm::length(camera.position - camera.target), 0.9f * distance, 1e-4f);
  zoomCamera(camera, 1000.0f);
  EXPECT_GT(glm::length(camera.position - camera.target), 0.0f);
}

// In the plane the light keeps its height; along the line it moves only vertically (mouse up:
// up).
TEST(CameraControl, LightDragsInItsPlaneOrAlongTheVertical) {
  const Camera camera = testCamera();
  Light light;
  light.center = vec3(1.0f, 5.0f, 0.0f);
  Light in_plane = light;
  dragLight(in_plane, camera, 40.0f, -20.0f, 400, false);
  EXPECT_EQ(in_plane.center.y, light.center.y);
  EXPECT_GT(in_plane.center.x, light.center.x);  // right on screen: right in the world
  EXPECT_LT(in_plane.center.z, light.center.z);  // mouse up: away from the camera
  Light vertical = light;
  dragLight(vertical, camera, 40.0f, -20.0f, 400, true);
  EXPECT_EQ(vertical.center.x, light.center.x);
  EXPECT_EQ(vertical.center.z, light.center.z);
  EXPECT_GT(vertical.center.y, light.center.y);
}

}  // namespace test_camera_control
}  // namespace penumbra::viewer
