#include "scene/mesh_ops.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "scene/normals.h"
#include "scene/weld.h"

namespace penumbra {

namespace {

// glm::normalize, except for vectors whose squared length leaves float's range (a normal
// matrix that scales by 1e20 or 1e-20): those are scaled to their largest component first.
vec3 normalizeWide(const vec3& v) {
  const vec3 n = glm::normalize(v);
  if (isFinite(n) && n != vec3(0.0f)) return n;  // an overflowed length gives zero
  const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return largest > 0.0f && std::isfinite(largest) ? glm::normalize(v / largest) : n;
}

}  // namespace

void transformMesh(Mesh& mesh, const mat4& transform) {
  const mat3 linear(transform);
  // The determinant in double: a uniform scale of 2e13 or 2e-15 (framing a mesh 1e-13 or 1e15
  // units across) is a fine transform whose float determinant overflows or underflows.
  const double det = glm::determinant(glm::dmat3(linear));
  PENUMBRA_CHECK(isFinite(linear[0]) && isFinite(linear[1]) && isFinite(linear[2]) &&
                     isFinite(vec3(transform[3])),
                 "mesh '{}': the transform is not finite", mesh.name);
  PENUMBRA_CHECK(det != 0.0, "mesh '{}': the transform is singular (it flattens the mesh)",
                 mesh.name);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const vec3 p = vec3(transform * vec4(mesh.positions[i], 1.0f));
    PENUMBRA_CHECK(isFinite(p),
                   "mesh '{}': the transform moves vertex {} ({}, {}, {}) out of float range "
                   "({}, {}, {})",
                   mesh.name, i, mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z,
                   p.x, p.y, p.z);
    mesh.positions[i] = p;
  }
  // The inverse in float, unless the float determinant overflows (a scale of 2e13: the inverse
  // would come out zero) or is subnormal (2e-15: infinite): then in double.
  const float float_det = glm::determinant(linear);
  mat3 normal_matrix = std::isnormal(float_det) ? glm::transpose(glm::inverse(linear)) : mat3(0.0f);
  if (!std::isnormal(float_det) || !isFinite(normal_matrix[0]) || !isFinite(normal_matrix[1]) ||
      !isFinite(normal_matrix[2])) {
    normal_matrix = mat3(glm::transpose(glm::inverse(glm::dmat3(linear))));
  }
  for (vec3& n : mesh.corner_normals) n = normalizeWide(normal_matrix * n);
  if (det < 0.0) {
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
