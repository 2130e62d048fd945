#pragma once
// What loading made of a mesh, one line per mesh after `penumbra render` loads a scene and the
// same numbers in the stats JSON: so a file that loads as something other than its author meant
// (a strip PLY read as one triangle, a scan full of holes) is visible, not silent.
#include <string>

#include "scene/edges.h"
#include "scene/mesh.h"

namespace penumbra {

struct MeshReport {
  std::string name;
  bool from_file = false;
  // As the loader delivers them, before welding (0 for generated meshes): assimp gives OBJ
  // files one vertex per face corner, PLY and glTF files their own vertex lists.
  size_t file_vertices = 0;
  size_t file_triangles = 0;    // read, before dropping degenerate ones
  size_t triangles = 0;         // kept
  size_t welded_vertices = 0;   // after welding equal positions
  size_t degenerate_dropped = 0;
  size_t open_edges = 0;         // used by one triangle
  size_t non_manifold_edges = 0;  // used by three or more
  size_t components = 0;         // triangles connected through shared (welded) vertices
};

MeshReport reportMesh(const Mesh& mesh, const EdgeAdjacency& adjacency);
// "bunny.obj: 3674 triangles, 11022 vertices read, 1839 after welding, 0 open edges, 0
// non-manifold edges, 0 degenerate triangles dropped, 1 component"
std::string meshReportLine(const MeshReport& report);

}  // namespace penumbra
