#pragma once
// A bounding volume hierarchy over the scene's objects for occlusion culling
// (docs/occlusion-culling.md): every mesh is an object (a scene's instances are flattened into
// meshes, so each instance is one), and a mesh of more than kClusterTriangles triangles is cut
// into clusters of spatially coherent triangles, each an object of its own. Built once per scene.
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace penumbra {

// Most clusters hold between half this and this many triangles: a few hundred, so a cluster's
// box is tight enough to be hidden behind a wall while the per-cluster test stays a small cost
// next to rasterizing its triangles.
inline constexpr uint32_t kClusterTriangles = 64;

struct ObjectCluster {
  Bounds3 bounds;        // world space, of its triangles' vertices
  uint32_t mesh = 0;     // index into Scene::meshes
  uint32_t first = 0;    // its triangles: ObjectHierarchy::triangles[first, first + count)
  uint32_t count = 0;
};

struct ObjectNode {
  Bounds3 bounds;
  // Leaf: cluster index in `first`, count == 1. Inner: children `first` and `first + 1`,
  // count == 0.
  uint32_t first = 0;
  uint32_t count = 0;
  bool leaf() const { return count != 0; }
};

struct ObjectHierarchy {
  std::vector<ObjectCluster> clusters;
  std::vector<uint32_t> triangles;  // global triangle ids, cluster after cluster, each ascending
  std::vector<uint32_t> cluster_of;  // per global triangle id, its cluster
  std::vector<ObjectNode> nodes;    // nodes[0] is the root (absent for an empty scene)
  // Per global triangle id, its three vertices' indices into EyeBuffers::clip_vertices (the
  // vertices of all meshes, mesh after mesh).
  std::vector<uint32_t> vertex_indices;
  size_t triangleCount() const { return cluster_of.size(); }
};

ObjectHierarchy buildObjectHierarchy(const Scene& scene);

}  // namespace penumbra
