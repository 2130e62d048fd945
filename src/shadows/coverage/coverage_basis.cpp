#include "shadows/coverage/coverage_basis.h"

#include <cmath>

#include "shadows/stages/light_sampling/light_sampling.h"

namespace penumbra {

void frontHalfPlane(const CoverageBasis& f, const dvec3& normal, dvec2& slope, double& offset) {
  // A light point y = p + n / inv_depth + t (X / scale_t - offset_t) + b (Y / scale_b - offset_b)
  // is in front when normal . (y - p) > 0: linear in (X, Y).
  offset = glm::dot(normal, f.n) / f.inv_depth - glm::dot(normal, f.t) * f.offset_t -
           glm::dot(normal, f.b) * f.offset_b;
  slope = dvec2(glm::dot(normal, f.t) / f.scale_t, glm::dot(normal, f.b) / f.scale_b);
}

double frontOfPlaneFraction(const CoverageBasis& f, const dvec3& normal) {
  dvec2 slope;
  double offset;
  frontHalfPlane(f, normal, slope, offset);
  return halfPlaneFraction(f.outline, slope, offset);
}

bool coverageBasis(const Light& light, const dvec3& p, CoverageBasis& f) {
  const dvec3 c(light.center);
  const dvec3 to_light = c - p;
  f.p = p;
  if (light.shape == LightShape::Sphere) {
    const double d = glm::length(to_light), r = light.radius;
    if (!(d > r * (1.0 + 1e-6))) return false;
    // One division for n and the depth, and the disk's scale beside it (not after it): the
    // basis is set up for every pixel an edge reaches, and its latency is that chain's.
    f.inv_depth = 1.0 / d;
    f.n = to_light * f.inv_depth;
    planeBasis(f.n, f.t, f.b);
    if (glm::dot(glm::cross(f.t, f.b), f.n) < 0.0) f.b = -f.b;
    f.offset_t = f.offset_b = 0.0;
    // 1 / the disk's radius r d / sqrt(D^2 - r^2).
    f.scale_t = f.scale_b = std::sqrt((d - r) * (d + r)) / (r * d);
    f.outline = LightOutline::Disk;
  } else {
    dvec3 normal, t, b;
    if (light.shape == LightShape::Disk) {
      normal = glm::normalize(dvec3(light.normal));
      planeBasis(normal, t, b);
      f.scale_t = f.scale_b = 1.0 / double(light.radius);
      f.outline = LightOutline::Disk;
    } else {
      t = glm::normalize(dvec3(light.edge_u));
      b = glm::normalize(dvec3(light.edge_v));
      normal = glm::cross(t, b);
      f.scale_t = 2.0 / glm::length(dvec3(light.edge_u));
      f.scale_b = 2.0 / glm::length(dvec3(light.edge_v));
      f.outline = LightOutline::Square;
    }
    if (glm::dot(glm::cross(t, b), normal) < 0.0) b = -b;
    double depth = glm::dot(normal, to_light);
    // Seen from the other side: flip the normal and one axis, keeping the basis right-handed.
    if (depth < 0.0) {
      normal = -normal;
      b = -b;
      depth = -depth;
    }
    if (!(depth > 1e-9 * (glm::length(to_light) + double(light.radius)))) return false;
    f.n = normal;
    f.t = t;
    f.b = b;
    f.inv_depth = 1.0 / depth;
    f.offset_t = glm::dot(-to_light, t);
    f.offset_b = glm::dot(-to_light, b);
  }
  return true;
}

}  // namespace penumbra
