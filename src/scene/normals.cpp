#include "scene/normals.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/vertex_triangles.h"

namespace penumbra {

namespace {

// Above this many triangles around one vertex, the per-corner grouping (quadratic in the
// valence) gives way to the simpler rule: the vertex average where the face is within the
// crease angle of it, else the face normal. Only fans with hundreds of triangles hit it.
constexpr uint32_t kMaxGroupedValence = 256;

// v / |v|, or zero for a zero v. A v whose squared length leaves float's range (the cross
// products of a mesh 1e-13 units across are 1e-26, their squares underflow) is normalised in
// double instead of being taken for zero.
vec3 unitOrZero(const vec3& v) {
  const float length = glm::length(v);
  if (length > 0.0f && std::isfinite(length)) return v / length;
  const glm::dvec3 wide(v);
  const double wide_length = glm::length(wide);
  return wide_length > 0.0 && std::isfinite(wide_length) ? vec3(wide / wide_length) : vec3(0.0f);
}

// Below this edge length a triangle's float cross product can underflow to zero although the
// triangle is not degenerate; edges over about 1e19 make it overflow. Either way its normal is
// then taken in double.
constexpr float kTinyEdge = 1e-9f;

}  // namespace

void computeCornerNormals(Mesh& mesh, float crease_degrees) {
  const size_t triangle_count = mesh.triangleCount();
  const size_t vertex_count = mesh.positions.size();
  const float cos_crease = std::cos(glm::radians(crease_degrees));

  // Area-weighted face normals: the cross product's length is twice the triangle's area.
  std::vector<vec3> weighted(triangle_count);
  std::vector<vec3> unit(triangle_count, vec3(0.0f));
  for (size_t t = 0; t < triangle_count; ++t) {
    const vec3 a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
    weighted[t] = glm::cross(b - a, c - a);
    unit[t] = unitOrZero(weighted[t]);
    const vec3 reach = glm::max(glm::abs(b - a), glm::abs(c - a));
    if (unit[t] == vec3(0.0f) &&
        (std::max({reach.x, reach.y, reach.z}) < kTinyEdge || !isFinite(weighted[t]))) {
      const glm::dvec3 wide = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
      unit[t] = unitOrZero(vec3(glm::normalize(wide)));
    }
  }

  const VertexTriangles rings = trianglesAroundVertices(mesh);
  const std::vector<uint32_t>& start = rings.start;
  const std::vector<uint32_t>& around = rings.around;

  std::vector<vec3> vertex_average(vertex_count, vec3(0.0f));
  for (size_t v = 0; v < vertex_count; ++v) {
    vec3 sum(0.0f);
    for (uint32_t i = start[v]; i < start[v + 1]; ++i) sum += weighted[around[i]];
    vertex_average[v] = unitOrZero(sum);
  }

  mesh.corner_normals.assign(mesh.indices.size(), vec3(0.0f, 1.0f, 0.0f));
  for (size_t t = 0; t < triangle_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.indices[3 * t + size_t(k)];
      vec3& out = mesh.corner_normals[3 * t + size_t(k)];
      const vec3& face = unit[t];
      if (face == vec3(0.0f)) {
        // Zero-area triangle: it covers no pixel, but give it its neighbours' normal.
        if (vertex_average[v] != vec3(0.0f)) out = vertex_average[v];
        continue;
      }
      if (start[v + 1] - start[v] > kMaxGroupedValence) {
        out = glm::dot(face, vertex_average[v]) >= cos_crease ? vertex_average[v] : face;
        continue;
      }
      // Smooth over the faces around v that bend less than the crease angle from this face, so
      // a cube corner stays faceted while a cylinder's side stays smooth up to its cap.
      vec3 sum(0.0f);
      for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
        const uint32_t f = around[i];
        if (glm::dot(unit[f], face) >= cos_crease) sum += weighted[f];
      }
      const vec3 smooth = unitOrZero(sum);
      out = smooth != vec3(0.0f) ? smooth : face;
    }
  }
}

}  // namespace penumbra
