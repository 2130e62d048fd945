#include "scene/mesh_ops.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "scene/normals.h"
#include "scene/weld.h"

namespace penumbra {

void transformMesh(Mesh& mesh, const mat4& transform) {
  const mat3 linear(transform);
  const float det = glm::determinant(linear);
  PENUMBRA_CHECK(std::isfinite(det) && det != 0.0f && isFinite(vec3(transform[3])),
                 "mesh '{}': the transform is singular or not finite", mesh.name);
  for (vec3& p : mesh.positions) p = vec3(transform * vec4(p, 1.0f));
  const mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  for (vec3& n : mesh.corner_normals) n = glm::normalize(normal_matrix * n);
  if (det < 0.0f) {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
      if (!mesh.corner_normals.empty()) {
        std::swap(mesh.corner_normals[3 * t + 1], mesh.corner_normals[3 * t + 2]);
      }
    }
  }
  weldPositions(mesh);
}

void appendMesh(Mesh& dst, const Mesh& src) {
  const bool keep_normals = (dst.indices.empty() || !dst.corner_normals.empty()) &&
                            !src.corner_normals.empty();
  if (!keep_normals) dst.corner_normals.clear();
  const uint32_t base = uint32_t(dst.positions.size());
  dst.positions.insert(dst.positions.end(), src.positions.begin(), src.positions.end());
  for (uint32_t i : src.indices) dst.indices.push_back(base + i);
  if (keep_normals) {
    dst.corner_normals.insert(dst.corner_normals.end(), src.corner_normals.begin(),
                              src.corner_normals.end());
  }
}

void finishMesh(Mesh& mesh, float crease_degrees) {
  weldPositions(mesh);
  if (mesh.corner_normals.empty()) computeCornerNormals(mesh, crease_degrees);
}

double signedVolume(const Mesh& mesh) {
  // Sum of the tetrahedra (origin, a, b, c), in double: exact enough for a test's sign.
  double volume = 0.0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
    volume += glm::dot(a, glm::cross(b, c));
  }
  return volume / 6.0;
}

}  // namespace penumbra
