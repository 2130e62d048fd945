#include "scene/flatten_instances.h"

#include "core/error.h"
#include "scene/mesh_ops.h"

namespace penumbra {

std::string instanceLabel(const Scene& scene, size_t index) {
  const MeshInstance& instance = scene.instances[index];
  if (!instance.name.empty()) return instance.name;
  const std::string prototype = instance.prototype < scene.prototypes.size() &&
                                        scene.prototypes[instance.prototype]
                                    ? scene.prototypes[instance.prototype]->name
                                    : std::string("instance");
  return fmt::format("{} #{}", prototype, index);
}

void flattenInstances(Scene& scene) {
  PENUMBRA_CHECK(scene.instance_meshes <= scene.instances.size() &&
                     scene.instance_meshes <= scene.meshes.size(),
                 "scene '{}': {} instance meshes counted for {} instances", scene.name,
                 scene.instance_meshes, scene.instances.size());
  // Counted before any copy, so that a file placing a large mesh millions of times is refused
  // with a message instead of running out of memory.
  uint64_t triangles = 0;
  for (const Mesh& mesh : scene.meshes) triangles += mesh.triangleCount();
  for (size_t i = scene.instance_meshes; i < scene.instances.size(); ++i) {
    const uint32_t prototype = scene.instances[i].prototype;
    if (prototype < scene.prototypes.size() && scene.prototypes[prototype])
      triangles += scene.prototypes[prototype]->triangleCount();
  }
  PENUMBRA_CHECK(triangles <= kMaxFlattenedTriangles,
                 "scene '{}': its meshes and {} instances hold {} triangles, more than the {} a "
                 "scene can render (each instance is a world-space copy, about 100 bytes a "
                 "triangle)",
                 scene.name, scene.instances.size(), triangles, kMaxFlattenedTriangles);
  scene.meshes.reserve(scene.meshes.size() + scene.instances.size() - scene.instance_meshes);
  for (size_t i = scene.instance_meshes; i < scene.instances.size(); ++i) {
    const MeshInstance& instance = scene.instances[i];
    const std::string label = fmt::format("instance {} ('{}')", i, instanceLabel(scene, i));
    PENUMBRA_CHECK(
        instance.prototype < scene.prototypes.size() && scene.prototypes[instance.prototype],
        "{}: prototype index {} is out of range (the scene has {} prototypes)", label,
        instance.prototype, scene.prototypes.size());
    PENUMBRA_CHECK(instance.material < scene.materials.size(),
                   "{}: material index {} is out of range (the scene has {} materials)", label,
                   instance.material, scene.materials.size());
    // The copy the techniques read: they all take world-space triangles (README, "Scenes").
    Mesh mesh = *scene.prototypes[instance.prototype];
    mesh.name = instanceLabel(scene, i);
    mesh.material = instance.material;
    mesh.file_counts = MeshFileCounts{};  // the prototype's file is reported once, not per copy
    if (instance.transform != mat4(1.0f)) {
      try {
        transformMesh(mesh, instance.transform);
      } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", label, e.what()));
      }
    }
    scene.meshes.push_back(std::move(mesh));
  }
  scene.instance_meshes = scene.instances.size();
}

}  // namespace penumbra
