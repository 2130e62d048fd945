#pragma once
// Helpers for assembling scenes in code (built-in scenes, mesh scenes, scene files).
#include <string>

#include "scene/scene.h"

namespace penumbra {

// Appends a material and returns its index.
uint32_t addMaterial(Scene& scene, const std::string& name, vec3 albedo, vec3 specular = vec3(0.0f),
                     float shininess = 32.0f);
// Appends a mesh with the given material; returns a reference to it in scene.meshes.
Mesh& addMesh(Scene& scene, Mesh mesh, uint32_t material);
// Appends a prototype (a mesh in object space, held once; instances.h) and returns its index.
uint32_t addPrototype(Scene& scene, Mesh mesh);
// Places prototype `prototype` with `transform` (object to world) and `material`.
void addInstance(Scene& scene, uint32_t prototype, const mat4& transform, uint32_t material);
void addLight(Scene& scene, vec3 center, float radius, vec3 color = vec3(1.0f),
              float intensity = 1.0f);

// A camera looking at `bounds` from direction `from` (target towards eye, need not be unit),
// far enough back that the bounding sphere fits a `width` x `height` image, times `margin`.
Camera frameBounds(const Bounds3& bounds, vec3 from, int width, int height, float fov_y = 40.0f,
                   float margin = 1.05f);

}  // namespace penumbra
