#include "shadows/facing_away.h"

namespace penumbra {

bool FacingAway::decide(uint32_t primitive) const {
  const auto [m, t] = scene_->locateTriangle(primitive);
  const Mesh& mesh = scene_->meshes[m];
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  const double eye_side = glm::dot(n, eye_ - a);
  bool away = false;
  if (length > 0.0 && eye_side != 0.0) {
    if (eye_side < 0.0) n = -n;
    const double light_side = glm::dot(n / length, centre_ - a);
    away = radius_ > 0.0 ? light_side < -radius_ : light_side < 0.0;
  }
  known_[primitive].store(away ? kAway : kLit, std::memory_order_relaxed);
  return away;
}

}  // namespace penumbra
