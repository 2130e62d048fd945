#pragma once
// The scene's triangles in an Embree 3 BVH, for the oracle's shadow rays. Every triangle of every
// mesh is an occluder from both sides (Embree's back-face culling is off), whatever the mesh's
// orientation or closedness: a shadow ray only asks whether anything is in the way.
#include <cstddef>
#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"

namespace penumbra {

// A segment origin + t * direction, t in [0, tfar]. direction need not be unit length.
struct ShadowRay {
  vec3 origin;
  vec3 direction;
  float tfar = 0.0f;
};

class EmbreeScene {
 public:
  // Builds the BVH of all meshes (robust mode, so rays through edges and vertices are not
  // missed). Throws penumbra::Error on a malformed mesh (index out of range, non-finite
  // position) or when Embree reports an error.
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // blocked[i] = 1 when a triangle crosses rays[i], else 0. packets: trace 16 rays per call
  // (rtcOccluded16) instead of one per call (rtcOccluded1); both give the same answers (tests).
  // Thread-safe.
  void occluded(const ShadowRay* rays, size_t count, bool packets, uint8_t* blocked) const;

 private:
  void* scene_ = nullptr;  // RTCScene, kept out of this header so only one file sees Embree
};

}  // namespace penumbra
