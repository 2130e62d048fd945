#pragma once
// An indexed triangle mesh in world space, with positions welded so that edge adjacency sees
// shared edges (see weld.h). Meshes are not assumed to be closed 2-manifolds: open edges and
// edges shared by three or more triangles are kept as they are (see edges.h).
#include <cstdint>
#include <string>
#include <vector>

#include <penumbra/core/math.h>

namespace penumbra {

// What a loader read from a mesh file, before welding (src/scene/mesh_report.h prints it). All
// zero for generated meshes.
struct MeshFileCounts {
  size_t vertices = 0;            // as the loader delivers them (OBJ: one per face corner)
  size_t triangles = 0;           // after triangulating polygons, before dropping degenerate ones
  size_t degenerate_dropped = 0;  // triangles welding made degenerate (a repeated vertex)
  // Problems that still left a mesh, e.g. most vertices used by no triangle: printed as
  // warnings, never dropped silently.
  std::vector<std::string> warnings;
};

struct Mesh {
  std::string name;                // file name or generator name, for messages
  std::vector<vec3> positions;     // welded: no two are bitwise equal (and no -0.0)
  std::vector<uint32_t> indices;   // 3 per triangle, counter-clockwise seen from the front
  // Shading normals, 3 per triangle (one per corner), unit length. Filled by the loader from the
  // file or computed (see normals.h); never used for shadows, which use geometry only.
  std::vector<vec3> corner_normals;
  uint32_t material = 0;           // index into Scene::materials
  // True when every edge is shared by exactly two triangles that traverse it in opposite
  // directions (a closed, consistently oriented 2-manifold). Set by buildEdges().
  bool closed = false;
  MeshFileCounts file_counts;      // filled by loadMesh

  size_t triangleCount() const { return indices.size() / 3; }
  vec3 vertex(size_t triangle, int corner) const {
    return positions[indices[triangle * 3 + size_t(corner)]];
  }
  Bounds3 bounds() const {
    Bounds3 b;
    for (const vec3& p : positions) b.extend(p);
    return b;
  }
};

}  // namespace penumbra
