#pragma once
// A scene: world-space meshes with their edge adjacency, materials, lights, camera and the
// render settings a scene file may carry.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <penumbra/scene/camera.h>
#include <penumbra/scene/edges.h>
#include <penumbra/scene/instances.h>
#include <penumbra/scene/light.h>
#include <penumbra/scene/material.h>
#include <penumbra/scene/mesh.h>
#include <penumbra/scene/path.h>

namespace penumbra {

struct RenderSettings {
  int width = 640;
  int height = 427;   // the papers' image size
  vec3 ambient{0.12f};  // ambient light, linear RGB, added after visibility (papers' order)
  vec3 background{0.02f, 0.02f, 0.03f};
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  // Meshes placed many times (instances.h). Each prototype is held once, in object space, and
  // shared by every instance and every copy of the scene. The techniques read world-space
  // meshes, so finalize() appends one transformed copy per instance to `meshes`
  // (flattenInstances, src/scene/flatten_instances.cpp): the last `instance_meshes` entries of
  // `meshes` are those copies, in the order of `instances`, and cost the memory of the triangles
  // they hold (docs/scene-format.md, "instances", gives the figures).
  std::vector<std::shared_ptr<const Mesh>> prototypes;
  std::vector<MeshInstance> instances;
  size_t instance_meshes = 0;
  std::vector<EdgeAdjacency> adjacency;  // one per mesh, same order
  // triangle_offsets[i] is the global id of mesh i's first triangle (see EyeBuffers::primitive);
  // one extra entry at the end holds the total. Filled by finalize().
  std::vector<uint32_t> triangle_offsets;
  std::vector<Material> materials;       // at least one
  std::vector<Light> lights;
  Camera camera;
  RenderSettings settings;
  ScenePath path;  // keyframed camera and lights for `penumbra render --path` (path.h)

  Bounds3 bounds() const {
    Bounds3 b;
    for (const Mesh& m : meshes) b.extend(m.bounds());
    return b;
  }
  size_t triangleCount() const {
    size_t n = 0;
    for (const Mesh& m : meshes) n += m.triangleCount();
    return n;
  }
  // Mesh index and triangle index within it of a global triangle id.
  std::pair<uint32_t, uint32_t> locateTriangle(uint32_t global_id) const;
  // Appends the world-space copies of the instances that have none yet (instance_meshes counts
  // those that have), then builds triangle offsets, adjacency for every mesh and checks the
  // scene is renderable (throws penumbra::Error naming what is wrong: no lights, non-finite
  // values, negative radius, bad material index, an instance of a missing prototype).
  void finalize();
};

}  // namespace penumbra
