#pragma once
// The triangles around every vertex of every mesh (global ids, EyeBuffers::primitive), for the
// exact soft shadow volumes' look at the triangles next to a visible one (exact_technique.cpp).
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

class VertexRings {
 public:
  explicit VertexRings(const Scene& scene);
  // The triangles other than `id` sharing a vertex with it, each once, into `out` (cleared).
  void neighbours(uint32_t id, std::vector<uint32_t>& out) const;

 private:
  const Scene& scene_;
  std::vector<std::vector<uint32_t>> first_;      // per mesh, per vertex then the end
  std::vector<std::vector<uint32_t>> triangles_;  // per mesh, global ids grouped by vertex
};

}  // namespace penumbra
