#include "scene/weld.h"

#include <vector>

#include <meshoptimizer.h>

#include "core/error.h"

namespace penumbra {

size_t weldPositions(Mesh& mesh) {
  const size_t vertex_count = mesh.positions.size();
  const size_t index_count = mesh.indices.size();
  PENUMBRA_CHECK(index_count % 3 == 0, "mesh '{}': {} indices is not a whole number of triangles",
                 mesh.name, index_count);
  PENUMBRA_CHECK(mesh.corner_normals.empty() || mesh.corner_normals.size() == index_count,
                 "mesh '{}': {} corner normals for {} corners", mesh.name,
                 mesh.corner_normals.size(), index_count);
  for (size_t i = 0; i < index_count; ++i) {
    PENUMBRA_CHECK(mesh.indices[i] < vertex_count,
                   "mesh '{}': triangle {} references vertex {} but the mesh has {} vertices",
                   mesh.name, i / 3, mesh.indices[i], vertex_count);
  }

  // meshoptimizer compares vertices bytewise; -0.0 and +0.0 differ in their sign bit but are
  // the same point, so canonicalise first (x == 0 holds for both).
  for (vec3& p : mesh.positions) {
    for (int axis = 0; axis < 3; ++axis) {
      if (p[axis] == 0.0f) p[axis] = 0.0f;
    }
  }

  // remap[old] = new vertex, in order of first use; unreferenced vertices get ~0u.
  std::vector<unsigned int> remap(vertex_count);
  const size_t unique_count =
      meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), index_count,
                                  mesh.positions.data(), vertex_count, sizeof(vec3));
  std::vector<vec3> unique_positions(unique_count);
  meshopt_remapVertexBuffer(unique_positions.data(), mesh.positions.data(), vertex_count,
                            sizeof(vec3), remap.data());

  // Drop triangles that welding made degenerate, keeping corner normals aligned with the
  // surviving triangles. Vertices only such triangles used become unreferenced: compact below.
  size_t kept = 0;
  const bool has_normals = !mesh.corner_normals.empty();
  for (size_t t = 0; t < index_count / 3; ++t) {
    const uint32_t a = remap[mesh.indices[3 * t]];
    const uint32_t b = remap[mesh.indices[3 * t + 1]];
    const uint32_t c = remap[mesh.indices[3 * t + 2]];
    if (a == b || b == c || a == c) continue;
    mesh.indices[3 * kept] = a;
    mesh.indices[3 * kept + 1] = b;
    mesh.indices[3 * kept + 2] = c;
    if (has_normals) {
      for (int k = 0; k < 3; ++k) mesh.corner_normals[3 * kept + k] = mesh.corner_normals[3 * t + k];
    }
    ++kept;
  }
  const size_t dropped = index_count / 3 - kept;
  mesh.indices.resize(3 * kept);
  if (has_normals) mesh.corner_normals.resize(3 * kept);

  constexpr uint32_t kUnused = ~0u;
  std::vector<uint32_t> compact(unique_count, kUnused);
  mesh.positions.clear();
  mesh.positions.reserve(unique_count);
  for (uint32_t& index : mesh.indices) {
    if (compact[index] == kUnused) {
      compact[index] = uint32_t(mesh.positions.size());
      mesh.positions.push_back(unique_positions[index]);
    }
    index = compact[index];
  }
  return dropped;
}

}  // namespace penumbra
