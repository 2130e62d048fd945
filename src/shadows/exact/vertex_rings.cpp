#include "shadows/exact/vertex_rings.h"

#include <algorithm>

namespace penumbra {

VertexRings::VertexRings(const Scene& scene)
    : scene_(scene), first_(scene.meshes.size()), triangles_(scene.meshes.size()) {
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    std::vector<uint32_t>& first = first_[m];
    first.assign(mesh.positions.size() + 1, 0);
    for (const uint32_t v : mesh.indices) ++first[v + 1];
    for (size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
    std::vector<uint32_t>& triangles = triangles_[m];
    triangles.resize(mesh.indices.size());
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (size_t i = 0; i < mesh.indices.size(); ++i)
      triangles[next[mesh.indices[i]]++] = scene.triangle_offsets[m] + uint32_t(i / 3);
  }
}

void VertexRings::neighbours(uint32_t id, std::vector<uint32_t>& out) const {
  out.clear();
  const auto [m, t] = scene_.locateTriangle(id);
  const Mesh& mesh = scene_.meshes[m];
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = mesh.indices[size_t(t) * 3 + size_t(k)];
    for (uint32_t i = first_[m][v]; i < first_[m][v + 1]; ++i)
      if (triangles_[m][i] != id) out.push_back(triangles_[m][i]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace penumbra
