#include "shadows/stages/silhouettes/edge_on_sheet.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/parallel.h"

namespace penumbra {

bool edgeOnToLight(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& light,
                   double tolerance) {
  const dvec3 normal = glm::cross(b - a, c - a);
  const double length = glm::length(normal);
  return length > 0.0 && std::fabs(glm::dot(normal, light - a)) <= tolerance * length;
}

bool anyEdgeOnToLight(const Scene& scene, const Light& light) {
  const dvec3 l(light.center);
  const double tolerance = kEdgeOnRelative * double(light.radius);
  for (const Mesh& mesh : scene.meshes) {
    const size_t n = mesh.triangleCount();
    std::vector<uint8_t> found((n + 8191) / 8192, 0);
    parallelFor(found.size(), [&](size_t chunk) {
      const size_t end = std::min(n, (chunk + 1) * 8192);
      for (size_t t = chunk * 8192; t < end && !found[chunk]; ++t)
        found[chunk] = edgeOnToLight(dvec3(mesh.vertex(t, 0)), dvec3(mesh.vertex(t, 1)),
                                     dvec3(mesh.vertex(t, 2)), l, tolerance);
    });
    for (const uint8_t f : found)
      if (f) return true;
  }
  return false;
}

Silhouette edgeOnSheet(const Mesh& mesh, const EdgeAdjacency& adjacency, const Light& light,
                       const Silhouette& cast, int8_t facing) {
  Silhouette s;
  const size_t n = mesh.triangleCount();
  s.orientation.assign(n, 0);
  const dvec3 l(light.center);
  const double tolerance = kEdgeOnRelative * double(light.radius);
  parallelFor((n + 8191) / 8192, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 8192);
    for (size_t t = chunk * 8192; t < end; ++t)
      if (cast.orientation[t] != facing &&
          edgeOnToLight(dvec3(mesh.vertex(t, 0)), dvec3(mesh.vertex(t, 1)),
                        dvec3(mesh.vertex(t, 2)), l, tolerance))
        s.orientation[t] = facing;
  });
  for (const uint32_t t : adjacency.repeated.triangles) s.orientation[t] = 0;
  s.edges = silhouetteEdges(adjacency, s.orientation);
  return s;
}

}  // namespace penumbra
