#pragma once
// The one place where instances become world-space meshes (Scene::instances, instances.h).
#include <cstdint>

#include "scene/scene.h"

namespace penumbra {

// The most triangles a scene's meshes and instances may hold once flattened: every technique
// reads world-space triangles with adjacency, about 100 bytes each, so this is some 13 GB, and
// the largest built-in city (city:64) holds about 130 million.
inline constexpr uint64_t kMaxFlattenedTriangles = uint64_t(1) << 27;

// Appends to scene.meshes a transformed copy of every instance beyond the first
// scene.instance_meshes, and counts them there. Throws penumbra::Error naming the instance and
// what is wrong: a prototype or material index out of range, a singular or non-finite
// transform, a transform that moves a vertex out of float range; or, before copying anything,
// that the instances would take the scene past kMaxFlattenedTriangles.
void flattenInstances(Scene& scene);

// "<prototype name> #<index>" unless the instance is named.
std::string instanceLabel(const Scene& scene, size_t index);

}  // namespace penumbra
