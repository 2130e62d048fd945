#include "shadows/shadowmap/shadow_map_lookup.h"

#include <cmath>

namespace penumbra {

double receiverSlope(const Scene& scene, uint32_t primitive, const dvec3& p, const dvec3& light) {
  const auto [m, t] = scene.locateTriangle(primitive);
  const Mesh& mesh = scene.meshes[m];
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  const dvec3 n = glm::cross(b - a, c - a);
  const dvec3 l = light - p;
  const double nl = glm::length(n) * glm::length(l);
  const double cosine = nl > 0.0 ? std::fabs(glm::dot(n, l)) / nl : 1.0;
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  return sine < kMaxSlope * cosine ? sine / cosine : kMaxSlope;
}

}  // namespace penumbra
