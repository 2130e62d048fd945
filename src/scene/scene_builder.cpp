#include "scene/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "core/error.h"

namespace penumbra {

uint32_t addMaterial(Scene& scene, const std::string& name, vec3 albedo, vec3 specular,
                     float shininess) {
  scene.materials.push_back(Material{name, albedo, specular, shininess});
  return uint32_t(scene.materials.size() - 1);
}

Mesh& addMesh(Scene& scene, Mesh mesh, uint32_t material) {
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
  return scene.meshes.back();
}

uint32_t addPrototype(Scene& scene, Mesh mesh) {
  scene.prototypes.push_back(std::make_shared<const Mesh>(std::move(mesh)));
  return uint32_t(scene.prototypes.size() - 1);
}

void addInstance(Scene& scene, uint32_t prototype, const mat4& transform, uint32_t material) {
  MeshInstance instance;
  instance.prototype = prototype;
  instance.transform = transform;
  instance.material = material;
  scene.instances.push_back(std::move(instance));
}

void addLight(Scene& scene, vec3 center, float radius, vec3 color, float intensity) {
  scene.lights.push_back(Light{center, radius, color, intensity});
}

Camera frameBounds(const Bounds3& bounds, vec3 from, int width, int height, float fov_y,
                   float margin) {
  PENUMBRA_CHECK(!bounds.empty(), "cannot frame an empty scene");
  PENUMBRA_CHECK(glm::length(from) > 0.0f && width > 0 && height > 0,
                 "cannot frame a scene from a zero direction or into an empty image");
  const float radius = std::max(bounds.radius(), 1e-6f);
  const float half_y = glm::radians(fov_y) * 0.5f;
  const float half_x = std::atan(std::tan(half_y) * float(width) / float(height));
  const float distance = margin * radius / std::sin(std::min(half_x, half_y));
  Camera camera;
  camera.target = bounds.center();
  camera.position = camera.target + glm::normalize(from) * distance;
  camera.fov_y = fov_y;
  // Reversed-Z keeps precision at any distance, so the near plane only has to stay in front of
  // everything in view.
  camera.near_plane = std::max(1e-4f, 0.01f * (distance - radius));
  // Bounds near float's limit put the camera at infinity (or past View's 1e18 limit): say
  // that the scene is too large, not that the camera is not finite.
  const float reach = std::max({std::abs(camera.position.x), std::abs(camera.position.y),
                                std::abs(camera.position.z)});
  PENUMBRA_CHECK(std::isfinite(distance) && reach <= 1e18f,
                 "cannot place a camera around the scene: its bounds ({}, {}, {}) to ({}, {}, {}) "
                 "put it {:g} units from the origin (the limit is 1e18)",
                 bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x, bounds.max.y,
                 bounds.max.z, reach);
  return camera;
}

}  // namespace penumbra
