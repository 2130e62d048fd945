#include "shadows/stages/light_depth_maps/shadow_map_lookup.h"

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

namespace penumbra {

void LookupBatch::clear() {
  x.clear();
  sx.clear();
  sy.clear();
  w.clear();
  slope.clear();
}

void LookupBatch::add(int pixel_x, const MapPoint& m, double receiver_slope, int size) {
  x.push_back(pixel_x);
  sx.push_back(clampLookupPosition(m.sx, size));
  sy.push_back(clampLookupPosition(m.sy, size));
  w.push_back(m.w);
  slope.push_back(receiver_slope);
}

void LookupBatch::pad(int size) {
  while (sx.size() % kLookupBlock != 0) {
    sx.push_back(0.5 * size);
    sy.push_back(0.5 * size);
    w.push_back(0.0);
    slope.push_back(0.0);
  }
}

}  // namespace penumbra
