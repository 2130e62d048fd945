#include "scene/light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace penumbra {

vec3 LightTexture::at(vec2 st) const {
  const int i = std::clamp(int(std::floor(st.x * float(width))), 0, width - 1);
  const int j = std::clamp(int(std::floor(st.y * float(height))), 0, height - 1);
  return texels[size_t(j) * size_t(width) + size_t(i)];
}

std::shared_ptr<const LightTexture> makeLightTexture(int width, int height,
                                                     const std::vector<vec3>& texels,
                                                     const std::string& what) {
  PENUMBRA_CHECK(width >= 1 && height >= 1 && texels.size() == size_t(width) * size_t(height),
                 "{}: a light texture needs at least one texel ({}x{} with {} texels)", what,
                 width, height, texels.size());
  for (size_t k = 0; k < texels.size(); ++k) {
    const vec3& t = texels[k];
    PENUMBRA_CHECK(isFinite(t) && t.x >= 0.0f && t.y >= 0.0f && t.z >= 0.0f,
                   "{}: texel {} (column {}, row {}) is ({}, {}, {}): texels must be finite and "
                   ">= 0",
                   what, k, k % size_t(width), k / size_t(width), t.x, t.y, t.z);
  }
  auto texture = std::make_shared<LightTexture>();
  texture->width = std::min(width, kMaxLightTextureCells);
  texture->height = std::min(height, kMaxLightTextureCells);
  // Area box filter: output cell (i, j) averages the input texels over the part of the image it
  // covers, partial texels by their covered fraction (exact when the sizes divide).
  const double sx = double(width) / texture->width, sy = double(height) / texture->height;
  const auto overlap = [](double lo, double hi, int k) {
    return std::max(0.0, std::min(hi, double(k + 1)) - std::max(lo, double(k)));
  };
  dvec3 total(0.0);
  texture->texels.resize(size_t(texture->width) * size_t(texture->height));
  for (int j = 0; j < texture->height; ++j) {
    for (int i = 0; i < texture->width; ++i) {
      const double x0 = i * sx, x1 = (i + 1) * sx, y0 = j * sy, y1 = (j + 1) * sy;
      dvec3 sum(0.0);
      for (int y = int(y0); y < std::min(height, int(std::ceil(y1))); ++y) {
        const double wy = overlap(y0, y1, y);
        for (int x = int(x0); x < std::min(width, int(std::ceil(x1))); ++x) {
          sum += wy * overlap(x0, x1, x) * dvec3(texels[size_t(y) * size_t(width) + size_t(x)]);
        }
      }
      const dvec3 cell = sum / (sx * sy);
      texture->texels[size_t(j) * size_t(texture->width) + size_t(i)] = vec3(cell);
      total += cell;
    }
  }
  texture->mean = vec3(total / double(texture->texels.size()));
  PENUMBRA_CHECK(texture->mean.x + texture->mean.y + texture->mean.z > 0.0f,
                 "{}: the light texture is black everywhere (it would emit nothing)", what);
  return texture;
}

vec3 lightRadiance(const Light& light) {
  const vec3 radiance = light.color * light.intensity;
  return light.texture ? radiance * light.texture->mean : radiance;
}

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
      return std::numbers::pi * double(light.radius) * double(light.radius);
    case LightShape::Rectangle:
      return glm::length(glm::cross(dvec3(light.edge_u), dvec3(light.edge_v)));
  }
  return 0.0;
}

void checkLightShape(const Light& light) {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  PENUMBRA_CHECK(std::isfinite(light.radius) && light.radius >= 0.0f,
                 "light radius {} must be a finite number >= 0", light.radius);
  PENUMBRA_CHECK(!light.texture || light.shape == LightShape::Rectangle,
                 "a {} light cannot take a texture (only a rectangle light is textured)",
                 lightShapeName(light.shape));
  PENUMBRA_CHECK(!light.texture ||
                     (light.texture->width >= 1 && light.texture->height >= 1 &&
                      light.texture->width <= kMaxLightTextureCells &&
                      light.texture->height <= kMaxLightTextureCells &&
                      light.texture->texels.size() ==
                          size_t(light.texture->width) * size_t(light.texture->height)),
                 "light texture is malformed (make it with makeLightTexture)");
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
                     std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0)) * 180.0 /
                         std::numbers::pi);
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
