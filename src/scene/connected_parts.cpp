#include "scene/connected_parts.h"

#include <numeric>

namespace penumbra {

uint32_t connectedParts(const Mesh& mesh, std::vector<uint32_t>& part_of_vertex) {
  // Union-find over the vertices the triangles share (the mesh's positions are welded).
  std::vector<uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = find(mesh.indices[i]);
    parent[find(mesh.indices[i + 1])] = a;
    parent[find(mesh.indices[i + 2])] = a;
  }
  constexpr uint32_t kNone = ~0u;
  std::vector<uint32_t> part_of_root(parent.size(), kNone);
  part_of_vertex.assign(parent.size(), 0);
  uint32_t parts = 0;
  for (const uint32_t v : mesh.indices) {
    uint32_t& part = part_of_root[find(v)];
    if (part == kNone) part = parts++;
    part_of_vertex[v] = part;
  }
  return parts;
}

}  // namespace penumbra
