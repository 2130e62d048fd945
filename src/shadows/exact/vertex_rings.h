#pragma once
// The triangles sharing a vertex with a visible one (global ids, EyeBuffers::primitive), for the
// exact soft shadow volumes' look at the triangles an origin may lie behind (pixel_edges.h:
// capCrossings).
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "scene/vertex_triangles.h"

namespace penumbra {

class VertexRings {
 public:
  explicit VertexRings(const Scene& scene);
  // The triangles other than `id` sharing a vertex with it, each once, into `out` (cleared).
  void neighbours(uint32_t id, std::vector<uint32_t>& out) const;

 private:
  const Scene& scene_;
  std::vector<VertexTriangles> meshes_;  // per mesh
};

}  // namespace penumbra
