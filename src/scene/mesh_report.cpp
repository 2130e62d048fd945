#include "scene/mesh_report.h"

#include <numeric>
#include <vector>

#include <fmt/format.h>

namespace penumbra {

namespace {

// Union-find over vertices: the connected components of the triangles.
size_t countComponents(const Mesh& mesh) {
  std::vector<uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = find(mesh.indices[i]);
    parent[find(mesh.indices[i + 1])] = a;
    parent[find(mesh.indices[i + 2])] = a;
  }
  std::vector<bool> used(mesh.positions.size(), false);
  for (uint32_t v : mesh.indices) used[v] = true;
  size_t components = 0;
  for (uint32_t v = 0; v < parent.size(); ++v) components += used[v] && find(v) == v;
  return components;
}

}  // namespace

MeshReport reportMesh(const Mesh& mesh, const EdgeAdjacency& adjacency) {
  MeshReport r;
  r.name = mesh.name;
  r.from_file = mesh.file_counts.vertices > 0;
  r.file_vertices = mesh.file_counts.vertices;
  r.file_triangles = mesh.file_counts.triangles;
  r.triangles = mesh.triangleCount();
  r.welded_vertices = mesh.positions.size();
  r.degenerate_dropped = mesh.file_counts.degenerate_dropped;
  r.open_edges = adjacency.open_edges;
  r.non_manifold_edges = adjacency.non_manifold_edges;
  r.components = countComponents(mesh);
  return r;
}

std::string meshReportLine(const MeshReport& r) {
  return fmt::format(
      "{}: {} triangles, {} vertices read, {} after welding, {} open edges, {} non-manifold "
      "edges, {} degenerate triangles dropped, {} component{}",
      r.name, r.triangles, r.from_file ? r.file_vertices : r.welded_vertices, r.welded_vertices,
      r.open_edges, r.non_manifold_edges, r.degenerate_dropped, r.components,
      r.components == 1 ? "" : "s");
}

}  // namespace penumbra
