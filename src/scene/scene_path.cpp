// Interpolating camera and light paths (path.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/scene.h"

namespace penumbra {

namespace {

// The index of the last key at or before `time` and the weight of the next one: linear
// interpolation, holding the end keys outside their range.
template <typename Key>
std::pair<size_t, float> bracket(const std::vector<Key>& keys, float time) {
  if (time <= keys.front().time) return {0, 0.0f};
  if (time >= keys.back().time) return {keys.size() - 1, 0.0f};
  size_t i = 0;
  while (keys[i + 1].time <= time) ++i;
  const float w = (time - keys[i].time) / (keys[i + 1].time - keys[i].time);
  return {i, w};
}

template <typename Key>
void checkKeyTimes(const std::vector<Key>& keys, const char* what) {
  PENUMBRA_CHECK(!keys.empty(), "path: {} has no keys", what);
  for (size_t k = 0; k < keys.size(); ++k) {
    PENUMBRA_CHECK(std::isfinite(keys[k].time), "path: {} key {}: time is not finite", what, k);
    PENUMBRA_CHECK(k == 0 || keys[k].time > keys[k - 1].time,
                   "path: {} key {}: time {} must be greater than the previous key's ({})", what,
                   k, keys[k].time, keys[k - 1].time);
  }
}

}  // namespace

float ScenePath::startTime() const {
  float t = std::numeric_limits<float>::infinity();
  if (!camera.empty()) t = camera.front().time;
  for (const LightPath& light : lights) {
    if (!light.keys.empty()) t = std::min(t, light.keys.front().time);
  }
  return std::isfinite(t) ? t : 0.0f;
}

float ScenePath::endTime() const {
  float t = -std::numeric_limits<float>::infinity();
  if (!camera.empty()) t = camera.back().time;
  for (const LightPath& light : lights) {
    if (!light.keys.empty()) t = std::max(t, light.keys.back().time);
  }
  return std::isfinite(t) ? t : 0.0f;
}

float ScenePath::frameTime(int frame) const {
  if (frames <= 1) return startTime();
  // In double, so that the last frame lands on the end time exactly.
  const double s = startTime(), e = endTime();
  return float(s + (e - s) * double(frame) / double(frames - 1));
}

void checkScenePath(const Scene& scene) {
  const ScenePath& path = scene.path;
  if (path.empty()) {
    PENUMBRA_CHECK(path.camera.empty() && path.lights.empty(),
                   "path: keys are given but no frames");
    return;
  }
  PENUMBRA_CHECK(path.frames >= 1, "path: frames must be >= 1 (got {})", path.frames);
  PENUMBRA_CHECK(!path.camera.empty() || !path.lights.empty(),
                 "path: moves neither the camera nor a light (give \"camera\" or \"lights\" keys)");
  if (!path.camera.empty()) {
    checkKeyTimes(path.camera, "camera");
    for (size_t k = 0; k < path.camera.size(); ++k) {
      const CameraKey& key = path.camera[k];
      PENUMBRA_CHECK(isFinite(key.position) && isFinite(key.target) && key.position != key.target,
                     "path: camera key {}: position and target must be finite and differ", k);
      PENUMBRA_CHECK(key.fov_y > 0.0f && key.fov_y < 180.0f,
                     "path: camera key {}: fov must be in (0, 180) degrees (got {})", k, key.fov_y);
    }
  }
  for (size_t i = 0; i < path.lights.size(); ++i) {
    const LightPath& light = path.lights[i];
    PENUMBRA_CHECK(light.light < scene.lights.size(),
                   "path: lights[{}]: light {} is out of range (the scene has {} lights)", i,
                   light.light, scene.lights.size());
    checkKeyTimes(light.keys, "light");
    for (size_t k = 0; k < light.keys.size(); ++k) {
      PENUMBRA_CHECK(isFinite(light.keys[k].center),
                     "path: lights[{}] key {}: centre is not finite", i, k);
    }
  }
}

void applyPathFrame(Scene& scene, int frame) {
  const ScenePath& path = scene.path;
  PENUMBRA_CHECK(!path.empty(), "scene '{}' has no path (docs/scene-format.md, \"path\")",
                 scene.name);
  PENUMBRA_CHECK(frame >= 0 && frame < path.frames,
                 "scene '{}': frame {} is out of range (its path has frames 0..{})", scene.name,
                 frame, path.frames - 1);
  const float time = path.frameTime(frame);
  if (!path.camera.empty()) {
    const auto [i, w] = bracket(path.camera, time);
    const CameraKey& a = path.camera[i];
    const CameraKey& b = path.camera[std::min(i + 1, path.camera.size() - 1)];
    scene.camera.position = glm::mix(a.position, b.position, w);
    scene.camera.target = glm::mix(a.target, b.target, w);
    scene.camera.fov_y = glm::mix(a.fov_y, b.fov_y, w);
  }
  for (const LightPath& light : path.lights) {
    const auto [i, w] = bracket(light.keys, time);
    const LightKey& a = light.keys[i];
    const LightKey& b = light.keys[std::min(i + 1, light.keys.size() - 1)];
    scene.lights[light.light].center = glm::mix(a.center, b.center, w);
  }
}

}  // namespace penumbra
