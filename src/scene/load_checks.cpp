#include "scene/load_checks.h"

#include <vector>

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra {

void checkPlyDeclaration(const std::string& path, const PlyHeader& ply) {
  if (!ply.is_ply) return;
  for (const PlyElement& element : ply.elements) {
    // igea.ply of common-3d-test-models: assimp returns a single triangle for the strips.
    if (element.name == "tristrips" && element.count > 0) {
      throw Error(fmt::format(
          "{}: the PLY stores its surface as triangle strips (element tristrips {}), which the "
          "loader does not read (it would give one triangle); convert the strips to faces "
          "first",
          path, element.count));
    }
  }
}

size_t countReferencedVertices(const Mesh& mesh) {
  std::vector<bool> used(mesh.positions.size(), false);
  size_t count = 0;
  for (uint32_t v : mesh.indices) {
    if (v < used.size() && !used[v]) {
      used[v] = true;
      ++count;
    }
  }
  return count;
}

void checkLoadedCounts(const std::string& path, const PlyHeader& ply, size_t referenced_vertices,
                       MeshFileCounts& counts) {
  for (const PlyElement& element : ply.elements) {
    if (element.name != "face" || element.count == 0) continue;
    // Every face gives at least one triangle: fewer means faces were lost on the way (faces of
    // one or two corners, which assimp keeps as points and lines).
    if (counts.triangles < element.count) {
      throw Error(fmt::format("{}: the PLY header declares {} faces but only {} triangles were "
                              "read from them",
                              path, element.count, counts.triangles));
    }
    // Polygons of dozens of corners on average are triangle strips written one face per strip;
    // triangulated as polygons they give fans of wrong triangles.
    constexpr uint64_t kStripLikeTrianglesPerFace = 16;
    if (counts.triangles > kStripLikeTrianglesPerFace * element.count) {
      counts.warnings.push_back(fmt::format(
          "{}: {} faces gave {} triangles ({} per face on average): are they triangle strips "
          "stored as polygons? The surface is probably wrong",
          path, element.count, counts.triangles, counts.triangles / element.count));
    }
  }
  // A surface uses nearly all of its vertices (a closed mesh has about twice as many triangles
  // as vertices); most of them unused means most of the surface did not load.
  if (counts.vertices >= 16 && referenced_vertices * 2 < counts.vertices) {
    counts.warnings.push_back(fmt::format(
        "{}: only {} of the file's {} vertices are used by the {} triangles read: most of the "
        "surface may not have loaded",
        path, referenced_vertices, counts.vertices, counts.triangles));
  }
}

}  // namespace penumbra
