#pragma once
// A scene: world-space meshes with their edge adjacency, materials, lights, camera and the
// render settings a scene file may carry.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <penumbra/scene/camera.h>
#include <penumbra/scene/edges.h>
#include <penumbra/scene/light.h>
#include <penumbra/scene/material.h>
#include <penumbra/scene/mesh.h>

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
  std::vector<EdgeAdjacency> adjacency;  // one per mesh, same order
  // triangle_offsets[i] is the global id of mesh i's first triangle (see EyeBuffers::primitive);
  // one extra entry at the end holds the total. Filled by finalize().
  std::vector<uint32_t> triangle_offsets;
  std::vector<Material> materials;       // at least one
  std::vector<Light> lights;
  Camera camera;
  RenderSettings settings;

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
  // Builds triangle offsets, adjacency for every mesh and checks the scene is renderable (throws penumbra::Error
  // naming what is wrong: no lights, non-finite values, negative radius, bad material index).
  void finalize();
};

}  // namespace penumbra
