#include "shadows/heckbert_herf/light_points.h"

#include "shadows/stages/light_sampling/light_sampling.h"

namespace penumbra {

std::vector<vec3> heckbertHerfPoints(const Light& light, int n, uint64_t seed,
                                     const vec3& toward) {
  std::vector<vec2> strata{size_t(n)};
  fixedSamples(n, seed, strata.data());
  Light planar = light;
  if (light.shape == LightShape::Sphere) {
    const dvec3 axis = dvec3(toward) - dvec3(light.center);
    const double length = glm::length(axis);
    planar.shape = LightShape::Disk;
    planar.normal = length > 0.0 ? vec3(axis / length) : vec3(0.0f, -1.0f, 0.0f);
  }
  std::vector<vec3> points{size_t(n)};
  for (int k = 0; k < n; ++k) points[size_t(k)] = vec3(planarLightPoint(planar, strata[size_t(k)]));
  return points;
}

}  // namespace penumbra
