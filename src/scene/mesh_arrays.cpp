#include "scene/mesh_arrays.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/normals.h"
#include "scene/weld.h"

namespace penumbra {

namespace {

void checkArrayShapes(const MeshArrays& arrays, const std::string& name) {
  PENUMBRA_CHECK(arrays.vertices.size() % 3 == 0,
                 "{}: the vertices hold {} numbers, not 3 (x, y, z) per vertex", name,
                 arrays.vertices.size());
  PENUMBRA_CHECK(arrays.triangles.size() % 3 == 0,
                 "{}: the triangles hold {} indices, not 3 per triangle", name,
                 arrays.triangles.size());
  PENUMBRA_CHECK(!arrays.vertices.empty(), "{}: the mesh has no vertices", name);
  PENUMBRA_CHECK(!arrays.triangles.empty(), "{}: the mesh has no triangles", name);
  PENUMBRA_CHECK(arrays.vertices.size() / 3 < std::numeric_limits<uint32_t>::max(),
                 "{}: {} vertices are more than 32-bit indices address", name,
                 arrays.vertices.size() / 3);
}

std::vector<vec3> checkedPositions(const std::vector<float>& vertices, const std::string& name) {
  std::vector<vec3> positions(vertices.size() / 3);
  for (size_t v = 0; v < positions.size(); ++v) {
    const vec3 p(vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]);
    PENUMBRA_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z),
                   "{}: vertex {} has a non-finite coordinate ({}, {}, {})", name, v, p.x, p.y,
                   p.z);
    positions[v] = p;
  }
  return positions;
}

std::vector<uint32_t> checkedIndices(const std::vector<int64_t>& triangles, size_t vertex_count,
                                     const std::string& name) {
  std::vector<uint32_t> indices(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const int64_t index = triangles[i];
    PENUMBRA_CHECK(index >= 0 && uint64_t(index) < vertex_count,
                   "{}: triangle {} (corner {}) uses vertex {}, out of range: there are {} "
                   "vertices (0..{})",
                   name, i / 3, i % 3, index, vertex_count, vertex_count - 1);
    indices[i] = uint32_t(index);
  }
  return indices;
}

}  // namespace

Mesh meshFromArrays(const MeshArrays& arrays, const std::string& name) {
  checkArrayShapes(arrays, name);
  Mesh mesh;
  mesh.name = name;
  mesh.positions = checkedPositions(arrays.vertices, name);
  mesh.indices = checkedIndices(arrays.triangles, mesh.positions.size(), name);
  mesh.file_counts.vertices = mesh.positions.size();
  mesh.file_counts.triangles = mesh.triangleCount();
  mesh.file_counts.degenerate_dropped = weldPositions(mesh);
  PENUMBRA_CHECK(!mesh.indices.empty(), "{}: every triangle is degenerate (repeated vertices)",
                 name);
  computeCornerNormals(mesh);
  return mesh;
}

}  // namespace penumbra
