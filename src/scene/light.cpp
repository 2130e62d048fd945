#include "scene/light.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace penumbra {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

std::string lightShapeName(LightShape shape) {
  switch (shape) {
    case LightShape::Sphere:
      return "sphere";
    case LightShape::Disk:
      return "disk";
    case LightShape::Rectangle:
      return "rectangle";
  }
  return "unknown";
}

Light diskLight(const vec3& center, const vec3& normal, float radius) {
  Light light;
  light.shape = LightShape::Disk;
  light.center = center;
  light.radius = radius;
  const float length = glm::length(normal);
  light.normal = length > 0.0f ? normal / length : normal;
  return light;
}

Light rectangleLight(const vec3& center, const vec3& edge_u, const vec3& edge_v) {
  Light light;
  light.shape = LightShape::Rectangle;
  light.center = center;
  light.edge_u = edge_u;
  light.edge_v = edge_v;
  light.radius = float(0.5 * glm::length(dvec3(edge_u) + dvec3(edge_v)));
  return light;
}

double lightArea(const Light& light) {
  switch (light.shape) {
    case LightShape::Sphere:
    case LightShape::Disk:
      return kPi * double(light.radius) * double(light.radius);
    case LightShape::Rectangle:
      return glm::length(glm::cross(dvec3(light.edge_u), dvec3(light.edge_v)));
  }
  return 0.0;
}

void checkLightShape(const Light& light) {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  PENUMBRA_CHECK(std::isfinite(light.radius) && light.radius >= 0.0f,
                 "light radius {} must be a finite number >= 0", light.radius);
  switch (light.shape) {
    case LightShape::Sphere:
      return;
    case LightShape::Disk: {
      const double length = glm::length(dvec3(light.normal));
      PENUMBRA_CHECK(isFinite(light.normal) && std::abs(length - 1.0) < 1e-4,
                     "disk light normal ({}, {}, {}) is not a unit vector", light.normal.x,
                     light.normal.y, light.normal.z);
      return;
    }
    case LightShape::Rectangle: {
      const dvec3 u(light.edge_u), v(light.edge_v);
      PENUMBRA_CHECK(isFinite(light.edge_u) && isFinite(light.edge_v),
                     "rectangle light edges are not finite");
      const double lu = glm::length(u), lv = glm::length(v);
      PENUMBRA_CHECK(lu > 0.0 && lv > 0.0, "rectangle light edge of length 0 (u {}, v {})", lu,
                     lv);
      PENUMBRA_CHECK(std::abs(glm::dot(u, v)) <= 1e-4 * lu * lv,
                     "rectangle light edges are not orthogonal (angle {:.4f} degrees)",
                     std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0)) * 180.0 / kPi);
      const double half_diagonal = 0.5 * glm::length(u + v);
      PENUMBRA_CHECK(std::abs(double(light.radius) - half_diagonal) <= 1e-5 * half_diagonal,
                     "rectangle light radius {} is not half its diagonal {} (use rectangleLight)",
                     light.radius, half_diagonal);
      return;
    }
  }
  throw Error("light shape is not sphere, disk or rectangle");
}

void requireSphereLight(const Light& light, const std::string& technique) {
  PENUMBRA_CHECK(light.shape == LightShape::Sphere,
                 "{} supports only spherical lights, not a {} light (use coverage, "
                 "heckbert-herf or reference)",
                 technique, lightShapeName(light.shape));
}

}  // namespace penumbra
