#include "scene/shapes.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"

namespace penumbra {

namespace {

// Angle of segment j of n, computed in double so that rings are symmetric to the last bit.
vec2 unitCircle(int j, int n) {
  const double a = 2.0 * std::numbers::pi * double(j) / double(n);
  return vec2(float(std::cos(a)), float(std::sin(a)));
}

// Any unit vector perpendicular to unit vector t.
vec3 anyPerpendicular(const vec3& t) {
  const vec3 axis = std::abs(t.x) < 0.6f ? vec3(1, 0, 0) : vec3(0, 1, 0);
  return glm::normalize(axis - glm::dot(axis, t) * t);
}

}  // namespace

Mesh makeLathe(vec3 base, const std::vector<vec2>& profile, int segments, float crease_degrees) {
  PENUMBRA_CHECK(profile.size() >= 2, "lathe: the profile needs at least 2 points");
  PENUMBRA_CHECK(segments >= 3, "lathe: {} segments is fewer than 3", segments);
  checkGeneratedTriangles("lathe", fmt::format("{} segments", segments).c_str(),
                          2 * int64_t(profile.size()) * segments);
  Mesh mesh;
  mesh.name = "lathe";
  // first[i]: index of ring i's first vertex; a pole ring has one vertex used for every j.
  std::vector<uint32_t> first(profile.size());
  std::vector<bool> pole(profile.size());
  for (size_t i = 0; i < profile.size(); ++i) {
    PENUMBRA_CHECK(profile[i].x >= 0.0f, "lathe: profile radius {} is negative", profile[i].x);
    first[i] = uint32_t(mesh.positions.size());
    pole[i] = profile[i].x == 0.0f;
    if (pole[i]) {
      mesh.positions.push_back(base + vec3(0.0f, profile[i].y, 0.0f));
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      const vec2 c = unitCircle(j, segments) * profile[i].x;
      mesh.positions.push_back(base + vec3(c.x, profile[i].y, c.y));
    }
  }
  auto at = [&](size_t i, int j) { return pole[i] ? first[i] : first[i] + uint32_t(j % segments); };
  // Quad (a, b) on ring i, (d, c) on ring i + 1, b and c one segment further round; with the
  // ring parametrised (r cos, y, r sin), (a, d, c) and (a, c, b) face away from the axis when the
  // profile climbs (and downwards along a bottom disk drawn outwards from the axis).
  for (size_t i = 0; i + 1 < profile.size(); ++i) {
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      if (d != c) mesh.indices.insert(mesh.indices.end(), {a, d, c});
      if (a != b) mesh.indices.insert(mesh.indices.end(), {a, c, b});
    }
  }
  finishMesh(mesh, crease_degrees);
  return mesh;
}

Mesh makeTube(const std::vector<vec3>& path, const std::vector<float>& radii, int sides, bool loop) {
  PENUMBRA_CHECK(path.size() >= 2 && radii.size() == path.size(),
                 "tube: needs at least 2 path points and one radius per point");
  PENUMBRA_CHECK(sides >= 3, "tube: {} sides is fewer than 3", sides);
  checkGeneratedTriangles("tube", fmt::format("{} sides", sides).c_str(),
                          2 * int64_t(path.size()) * sides);
  const size_t n = path.size();
  std::vector<vec3> tangent(n);
  for (size_t k = 0; k < n; ++k) {
    const vec3 next = k + 1 < n ? path[k + 1] : (loop ? path[0] : path[k]);
    const vec3 prev = k > 0 ? path[k - 1] : (loop ? path[n - 1] : path[k]);
    tangent[k] = glm::normalize(next - prev);
  }
  Mesh mesh;
  mesh.name = "tube";
  // Frame (normal, binormal, tangent) is right-handed; the ring runs from normal towards
  // binormal, so (a, b, c) and (a, c, d) below face outwards (b x t = n).
  vec3 normal = anyPerpendicular(tangent[0]);
  for (size_t k = 0; k < n; ++k) {
    normal = glm::normalize(normal - glm::dot(normal, tangent[k]) * tangent[k]);
    const vec3 binormal = glm::cross(tangent[k], normal);
    for (int j = 0; j < sides; ++j) {
      const vec2 c = unitCircle(j, sides);
      mesh.positions.push_back(path[k] + radii[k] * (c.x * normal + c.y * binormal));
    }
  }
  auto at = [&](size_t k, int j) { return uint32_t((k % n) * size_t(sides) + size_t(j % sides)); };
  const size_t rings = loop ? n : n - 1;
  for (size_t k = 0; k < rings; ++k) {
    for (int j = 0; j < sides; ++j) {
      const uint32_t a = at(k, j), b = at(k, j + 1), c = at(k + 1, j + 1), d = at(k + 1, j);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
  if (!loop) {
    const uint32_t start = uint32_t(mesh.positions.size());
    mesh.positions.push_back(path.front());
    const uint32_t end = uint32_t(mesh.positions.size());
    mesh.positions.push_back(path.back());
    for (int j = 0; j < sides; ++j) {
      mesh.indices.insert(mesh.indices.end(), {start, at(0, j + 1), at(0, j)});
      mesh.indices.insert(mesh.indices.end(), {end, at(n - 1, j), at(n - 1, j + 1)});
    }
  }
  finishMesh(mesh, 50.0f);
  return mesh;
}

Mesh makeTorus(vec3 center, float major_radius, float minor_radius, int segments, int sides) {
  PENUMBRA_CHECK(major_radius > minor_radius && minor_radius > 0.0f,
                 "torus: need major radius {} > minor radius {} > 0", major_radius, minor_radius);
  PENUMBRA_CHECK(segments >= 3, "torus: {} segments is fewer than 3", segments);
  PENUMBRA_CHECK(sides >= 3, "torus: {} sides is fewer than 3", sides);
  checkGeneratedTriangles("torus", fmt::format("{} segments x {} sides", segments, sides).c_str(),
                          2 * int64_t(segments) * sides);
  std::vector<vec3> path;
  for (int j = 0; j < segments; ++j) {
    const vec2 c = unitCircle(j, segments) * major_radius;
    path.push_back(center + vec3(c.x, 0.0f, c.y));
  }
  Mesh mesh = makeTube(path, std::vector<float>(path.size(), minor_radius), sides, true);
  mesh.name = "torus";
  return mesh;
}

}  // namespace penumbra
