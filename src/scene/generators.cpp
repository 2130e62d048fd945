#include "scene/generators.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "scene/mesh_ops.h"
#include "scene/shapes.h"

namespace penumbra {

Mesh makeBox(vec3 min, vec3 max) {
  PENUMBRA_CHECK(isFinite(min) && isFinite(max) && min.x < max.x && min.y < max.y && min.z < max.z,
                 "box: min ({}, {}, {}) must be below max ({}, {}, {}) on every axis", min.x,
                 min.y, min.z, max.x, max.y, max.z);
  Mesh mesh;
  mesh.name = "box";
  // Vertex i has x from bit 0, y from bit 1, z from bit 2 (0: min, 1: max).
  for (int i = 0; i < 8; ++i) {
    mesh.positions.push_back(vec3(i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z));
  }
  // Two triangles per face, counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  mesh.indices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                  2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  finishMesh(mesh);  // 45 degree crease: every corner takes its face's normal
  return mesh;
}

void checkGeneratedTriangles(const char* generator, const char* what, int64_t triangles) {
  PENUMBRA_CHECK(triangles <= kMaxGeneratedTriangles,
                 "{}: {} make {} triangles (the limit is {})", generator, what, triangles,
                 kMaxGeneratedTriangles);
}

Mesh makeSphere(vec3 center, float radius, int segments, int rings) {
  PENUMBRA_CHECK(radius > 0.0f && std::isfinite(radius), "sphere: radius {} must be > 0", radius);
  PENUMBRA_CHECK(rings >= 2, "sphere: {} rings is fewer than 2", rings);
  checkGeneratedTriangles("sphere", fmt::format("{} segments x {} rings", segments, rings).c_str(),
                          2 * int64_t(std::max(segments, 0)) * rings);
  // Profile from the south pole to the north pole; the poles have radius exactly 0 so the lathe
  // makes them single vertices and the sphere is closed.
  std::vector<vec2> profile;
  for (int i = 0; i <= rings; ++i) {
    const double theta = std::numbers::pi * double(i) / double(rings);
    const float r = (i == 0 || i == rings) ? 0.0f : float(radius * std::sin(theta));
    profile.push_back(vec2(r, float(-radius * std::cos(theta))));
  }
  Mesh mesh = makeLathe(center, profile, segments);
  mesh.name = "sphere";
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    mesh.corner_normals[i] = glm::normalize(mesh.positions[mesh.indices[i]] - center);
  }
  return mesh;
}

Mesh makeCylinder(vec3 base_center, float radius, float height, int segments) {
  PENUMBRA_CHECK(radius > 0.0f && height > 0.0f && std::isfinite(radius) && std::isfinite(height),
                 "cylinder: radius {} and height {} must be > 0", radius, height);
  Mesh mesh = makeLathe(base_center,
                        {vec2(0.0f, 0.0f), vec2(radius, 0.0f), vec2(radius, height), vec2(0.0f, height)},
                        segments);
  mesh.name = "cylinder";
  return mesh;
}

Mesh makeGroundPlane(vec3 center, float half_size) {
  PENUMBRA_CHECK(half_size > 0.0f && std::isfinite(half_size), "plane: half size {} must be > 0",
                 half_size);
  Mesh mesh;
  mesh.name = "plane";
  const float x0 = center.x - half_size, x1 = center.x + half_size;
  const float z0 = center.z - half_size, z1 = center.z + half_size;
  mesh.positions = {vec3(x0, center.y, z0), vec3(x0, center.y, z1), vec3(x1, center.y, z1),
                    vec3(x1, center.y, z0)};
  mesh.indices = {0, 1, 2, 0, 2, 3};  // (z1 - z0) x (x1 - x0) points to +y
  mesh.corner_normals.assign(6, vec3(0.0f, 1.0f, 0.0f));
  finishMesh(mesh);
  return mesh;
}

Mesh makeDisk(vec3 center, vec3 normal, float radius, int segments) {
  PENUMBRA_CHECK(radius > 0.0f && std::isfinite(radius), "disk: radius {} must be > 0", radius);
  PENUMBRA_CHECK(segments >= 3, "disk: {} segments is fewer than 3", segments);
  checkGeneratedTriangles("disk", fmt::format("{} segments", segments).c_str(), segments);
  PENUMBRA_CHECK(isFinite(normal) && glm::length(normal) > 0.0f, "disk: the normal is zero");
  const vec3 n = glm::normalize(normal);
  const vec3 axis = std::abs(n.x) < 0.6f ? vec3(1, 0, 0) : vec3(0, 1, 0);
  const vec3 u = glm::normalize(axis - glm::dot(axis, n) * n);
  const vec3 v = glm::cross(n, u);  // u x v = n: the fan below is counter-clockwise about n
  Mesh mesh;
  mesh.name = "disk";
  mesh.positions.push_back(center);
  for (int j = 0; j < segments; ++j) {
    const double a = 2.0 * std::numbers::pi * double(j) / double(segments);
    mesh.positions.push_back(center + radius * (float(std::cos(a)) * u + float(std::sin(a)) * v));
  }
  for (int j = 0; j < segments; ++j) {
    mesh.indices.insert(mesh.indices.end(),
                        {0u, uint32_t(1 + j), uint32_t(1 + (j + 1) % segments)});
  }
  mesh.corner_normals.assign(mesh.indices.size(), n);
  finishMesh(mesh);
  return mesh;
}

}  // namespace penumbra
