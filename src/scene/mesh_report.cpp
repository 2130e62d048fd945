#include "scene/mesh_report.h"

#include <vector>

#include <fmt/format.h>

#include "scene/connected_parts.h"

namespace penumbra {

namespace {

// The connected components of the triangles.
size_t countComponents(const Mesh& mesh) {
  std::vector<uint32_t> part_of_vertex;
  return connectedParts(mesh, part_of_vertex);
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
