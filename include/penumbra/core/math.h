#pragma once
// Vectors and matrices come from glm. World space is right-handed, y up; the camera looks down
// its -z axis (glm's lookAt convention).
#include <cmath>
#include <limits>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::ivec2;
using glm::mat3;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

// The z component of the cross product of two plane vectors: twice the signed area of the
// triangle they span, positive when b turns counter-clockwise from a.
inline double cross2(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

inline bool isFinite(const vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Axis-aligned box; empty when min > max.
struct Bounds3 {
  vec3 min{std::numeric_limits<float>::infinity()};
  vec3 max{-std::numeric_limits<float>::infinity()};
  void extend(const vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Bounds3& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  vec3 center() const { return (min + max) * 0.5f; }
  vec3 extent() const { return max - min; }
  float radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }
};

}  // namespace penumbra
