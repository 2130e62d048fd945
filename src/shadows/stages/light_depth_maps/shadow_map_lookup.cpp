#include "shadows/stages/light_depth_maps/shadow_map_lookup.h"

#include <cmath>

namespace penumbra {

dvec3 receiverNormal(const Scene& scene, uint32_t primitive, const dvec3& p, const dvec3& light) {
  const auto [m, t] = scene.locateTriangle(primitive);
  const Mesh& mesh = scene.meshes[m];
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  const dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  if (!(length > 0.0)) return dvec3(0.0);
  return glm::dot(n, light - p) >= 0.0 ? n / length : -n / length;
}

double receiverSlope(const dvec3& n, const dvec3& p, const dvec3& light) {
  const dvec3 l = light - p;
  const double nl = glm::length(n) * glm::length(l);
  const double cosine = nl > 0.0 ? std::fabs(glm::dot(n, l)) / nl : 1.0;
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  return sine < kMaxSlope * cosine ? sine / cosine : kMaxSlope;
}

dvec3 offsetAlongNormal(const LightDepthMaps& maps, const dvec3& p, const dvec3& n,
                        const MapPoint& m, double texels) {
  if (texels == 0.0) return p;
  return p + n * (texels * maps.texelSize(m.face, m.w));
}

ReceiverPlane receiverPlane(const LightDepthMaps& maps, int face, const dvec3& point,
                            const dvec3& n) {
  // The face's view basis as glm::lookAt builds it (forward, side, up), and the texel steps of
  // D(s) = forward + u tan_half side + v tan_half up, u = 2 sx / size - 1, v = 1 - 2 sy / size.
  const LightFace& f = maps.frustums.faces[size_t(face)];
  const dvec3 forward = glm::normalize(f.axis);
  const dvec3 side = glm::normalize(glm::cross(forward, f.up));
  const dvec3 up = glm::cross(side, forward);
  const double per_texel = 2.0 * maps.tan_half[size_t(face)] / maps.size;
  ReceiverPlane plane;
  plane.a = glm::dot(n, maps.centre - point);
  plane.step_x = glm::dot(n, side) * per_texel;
  plane.step_y = -glm::dot(n, up) * per_texel;
  return plane;
}

}  // namespace penumbra

namespace penumbra {

void LookupBatch::clear() {
  x.clear();
  for (std::vector<double>* v : {&sx, &sy, &w, &slope, &plane_a, &plane_x, &plane_y, &light_height})
    v->clear();
}

void LookupBatch::add(int pixel_x, const MapPoint& m, double receiver_slope,
                      const ReceiverPlane& plane, double height, int size) {
  x.push_back(pixel_x);
  sx.push_back(clampLookupPosition(m.sx, size));
  sy.push_back(clampLookupPosition(m.sy, size));
  w.push_back(m.w);
  slope.push_back(receiver_slope);
  plane_a.push_back(plane.a);
  plane_x.push_back(plane.step_x);
  plane_y.push_back(plane.step_y);
  light_height.push_back(height);
}

void LookupBatch::pad(int size) {
  while (sx.size() % kLookupBlock != 0) {
    sx.push_back(0.5 * size);
    sy.push_back(0.5 * size);
    w.push_back(0.0);
    slope.push_back(0.0);
    plane_a.push_back(0.0);
    plane_x.push_back(0.0);
    plane_y.push_back(0.0);
    light_height.push_back(0.0);
  }
}

}  // namespace penumbra
