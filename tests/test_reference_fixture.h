#pragma once
// Hand-built scenes and eye buffers for the oracle's tests: the eye pass is not used, so a
// rasterizer bug cannot hide an oracle bug (or the other way round). Every covered pixel sees
// a horizontal ground plane; its depth is computed analytically from the pixel-centre ray.
#include <cmath>
#include <vector>

#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"
#include "shadows/reference/reference_technique.h"

namespace penumbra::reference_test {

// Axis-aligned rectangle [x0, x1] x [z0, z1] in the plane y = height, two triangles facing +y.
inline Mesh horizontalQuad(const char* name, float height, float x0, float z0, float x1,
                           float z1) {
  Mesh m;
  m.name = name;
  m.positions = {vec3(x0, height, z0), vec3(x0, height, z1), vec3(x1, height, z1),
                 vec3(x1, height, z0)};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A horizontal disk at `height` centred on the y axis: a fan of `segments` triangles.
inline Mesh horizontalDisk(float height, float radius, int segments) {
  Mesh m;
  m.name = "disk";
  m.positions.push_back(vec3(0.0f, height, 0.0f));
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / segments;
    m.positions.push_back(vec3(float(radius * std::cos(a)), height, float(-radius * std::sin(a))));
  }
  for (int i = 0; i < segments; ++i) {
    m.indices.insert(m.indices.end(), {0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % segments)});
  }
  return m;
}

// A closed axis-aligned box (12 triangles).
inline Mesh box(vec3 lo, vec3 hi) {
  Mesh m;
  m.name = "box";
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back(vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
  }
  m.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
               2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return m;
}

inline Scene makeScene(std::vector<Mesh> meshes, const Light& light) {
  Scene scene;
  scene.name = "reference test";
  scene.meshes = std::move(meshes);
  scene.materials.emplace_back();
  scene.lights.push_back(light);
  scene.finalize();
  return scene;
}

// World point of the pixel-centre ray at (x + 0.5, y + 0.5) on the plane y = plane_y, or false
// when the ray misses it (parallel or behind the eye).
inline bool groundPoint(const View& view, double sx, double sy, double plane_y, dvec3& out) {
  const dvec3 eye(view.eye);
  const dvec3 direction = view.unprojectScreen(sx, sy, 1.0) - eye;  // through the near plane
  if (direction.y == 0.0) return false;
  const double t = (plane_y - eye.y) / direction.y;
  if (!(t > 0.0)) return false;
  out = eye + t * direction;
  return true;
}

// Eye buffers of a view that sees only the square ground [-half, half]^2 at y = plane_y, made
// by horizontalQuad as the scene's first mesh (triangle ids 0 and 1); pixels off it are
// background (tile z ranges are left empty: the oracle does not read them). depth = near /
// (distance along the view axis), stored as float like the eye pass stores it; each ground
// pixel names the triangle that holds its point, or `all_ids` when that is not kNoPrimitive.
inline EyeBuffers groundEyeBuffers(const View& view, double half, double plane_y,
                                   uint32_t all_ids = kNoPrimitive) {
  EyeBuffers eye;
  eye.depth.depth.resize(view.width, view.height, 0.0f);
  eye.primitive.resize(view.width, view.height, kNoPrimitive);
  const dmat4 world_to_view(view.view);
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      dvec3 g;
      if (!groundPoint(view, x + 0.5, y + 0.5, plane_y, g)) continue;
      if (std::abs(g.x) > half || std::abs(g.z) > half) continue;
      const double w = -(world_to_view * dvec4(g, 1.0)).z;
      eye.depth.depth.at(x, y) = float(double(view.near_plane) / w);
      // horizontalQuad's triangle 0 is the half with (x - x0) <= (z - z0) (diagonal x = z).
      eye.primitive.at(x, y) = all_ids != kNoPrimitive ? all_ids : (g.x <= g.z ? 0u : 1u);
    }
  }
  return eye;
}

inline int coveredPixels(const EyeBuffers& eye) {
  int n = 0;
  for (size_t i = 0; i < eye.depth.depth.size(); ++i) n += eye.depth.depth[i] > 0.0f ? 1 : 0;
  return n;
}

// The oracle prepared on the spot for one light (shadows/technique.h).
inline TechniqueResult renderReference(const TechniqueConfig& config, const Scene& scene,
                                       const Light& light, const View& view,
                                       const EyeBuffers& eye, const RenderContext& context = {}) {
  return renderShadows(config, scene, light, view, eye, context);
}

inline TechniqueConfig referenceConfig(int rays, uint64_t seed = 1, bool hard = false) {
  TechniqueConfig config("reference");
  ReferenceOptions& o = config.options<ReferenceOptions>();
  o.rays = rays;
  o.seed = seed;
  o.hard = hard;
  return config;
}

}  // namespace penumbra::reference_test
