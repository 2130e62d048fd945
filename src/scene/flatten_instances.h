#pragma once
// The one place where instances become world-space meshes (Scene::instances, instances.h).
#include "scene/scene.h"

namespace penumbra {

// Appends to scene.meshes a transformed copy of every instance beyond the first
// scene.instance_meshes, and counts them there. Throws penumbra::Error naming the instance and
// what is wrong: a prototype or material index out of range, a singular or non-finite
// transform, a transform that moves a vertex out of float range.
void flattenInstances(Scene& scene);

// "<prototype name> #<index>" unless the instance is named.
std::string instanceLabel(const Scene& scene, size_t index);

}  // namespace penumbra
