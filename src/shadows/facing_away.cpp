#include "shadows/facing_away.h"

#include "core/parallel.h"

namespace penumbra {

void shadowFacingAway(const Scene& scene, const Light& light, const View& view,
                      const EyeBuffers& eye, Image<float>& visibility) {
  const dvec3 eye_position(view.eye), centre(light.center);
  const double radius = light.radius;
  parallelFor(size_t(visibility.height()), [&](size_t row) {
    const int y = int(row);
    uint32_t cached = kNoPrimitive;
    bool away = false;
    for (int x = 0; x < visibility.width(); ++x) {
      const uint32_t id = eye.primitive.at(x, y);
      if (id == kNoPrimitive || !(eye.depth.depth.at(x, y) > 0.0f)) continue;
      if (id != cached) {
        cached = id;
        const auto [m, t] = scene.locateTriangle(id);
        const Mesh& mesh = scene.meshes[m];
        const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
        dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        const double eye_side = glm::dot(n, eye_position - a);
        away = false;
        if (length > 0.0 && eye_side != 0.0) {
          if (eye_side < 0.0) n = -n;
          const double light_side = glm::dot(n / length, centre - a);
          away = radius > 0.0 ? light_side < -radius : light_side < 0.0;
        }
      }
      if (away) visibility.at(x, y) = 0.0f;
    }
  });
}

}  // namespace penumbra
