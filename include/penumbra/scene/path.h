#pragma once
// Camera and light paths: keyframes that move the camera (a walkthrough) and lights (a moving
// sun or lamp) over a sequence of frames (docs/scene-format.md, "path"). Between keys the values
// are interpolated linearly in time; before the first key and after the last they hold.
#include <cstdint>
#include <vector>

#include <penumbra/core/math.h>

namespace penumbra {

struct Scene;

struct CameraKey {
  float time = 0.0f;
  vec3 position{0.0f};
  vec3 target{0.0f};
  float fov_y = 45.0f;  // degrees
};

struct LightKey {
  float time = 0.0f;
  vec3 center{0.0f};
};

struct LightPath {
  uint32_t light = 0;  // index into Scene::lights
  std::vector<LightKey> keys;
};

struct ScenePath {
  int frames = 0;                  // 0: the scene has no path
  std::vector<CameraKey> camera;   // empty: the camera stays
  std::vector<LightPath> lights;   // lights not listed stay
  bool empty() const { return frames == 0; }
  // The first and last key time over all keys: frame k is at start + (end - start) * k /
  // (frames - 1) (one frame: at start).
  float startTime() const;
  float endTime() const;
  float frameTime(int frame) const;
};

// Moves `scene`'s camera and the lights its path names to where the path puts them at `frame`
// (0 <= frame < scene.path.frames). Throws penumbra::Error naming the scene when it has no path
// or the frame is out of range.
void applyPathFrame(Scene& scene, int frame);

// Checks a path against its scene: at least one key, key times finite and strictly increasing,
// light indices in range, camera keys with distinct position and target. Throws
// penumbra::Error naming the key. Called by Scene::finalize().
void checkScenePath(const Scene& scene);

}  // namespace penumbra
