#include "shadows/stages/silhouettes/facing_away.h"

#include <cmath>

namespace penumbra {

uint8_t FacingAway::decide(uint32_t primitive) const {
  const auto [m, t] = scene_->locateTriangle(primitive);
  const Mesh& mesh = scene_->meshes[m];
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  const double eye_side = glm::dot(n, eye_ - a);
  uint8_t state = kAcross;
  if (length > 0.0 && eye_side != 0.0 && std::isfinite(eye_side)) {
    if (eye_side < 0.0) n = -n;
    const double light_side = glm::dot(n / length, centre_ - a);
    if (radius_ > 0.0 ? light_side < -radius_ : light_side < 0.0) {
      state = kAway;
    } else if (light_side > radius_ * (1.0 + kClearMargin)) {
      state = kClear;
    }
  }
  known_[primitive].store(state, std::memory_order_relaxed);
  return state;
}

}  // namespace penumbra
