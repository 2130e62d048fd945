#include "shadows/stages/light_depth_maps/light_depth_maps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/rasterizer.h"

namespace penumbra {
namespace {

// The near plane of every face, as a fraction of the distance from the light centre to the
// farthest corner of the scene's bounds. Reversed-Z float depth (near / w) keeps the same
// relative precision at every distance, so a small near plane costs no depth precision; it only
// clips away geometry closer to the light than this (1e-6 of the scene: nothing in practice),
// whatever the scene's units.
constexpr double kNearFraction = 1e-6;

}  // namespace

SceneTriangles::SceneTriangles(const Scene& scene) {
  size_t base = 0;
  for (const Mesh& mesh : scene.meshes) {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      triangles.add(uint32_t(base + mesh.indices[t * 3]), uint32_t(base + mesh.indices[t * 3 + 1]),
                    uint32_t(base + mesh.indices[t * 3 + 2]), 0, 0);
    }
    base += mesh.positions.size();
  }
  vertex_count = base;
}

MapPoint LightDepthMaps::project(const dvec3& p) const {
  MapPoint m;
  if (frustums.cube()) {
    const dvec3 d = p - centre;
    const dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z)
      m.face = d.x >= 0.0 ? 0 : 1;
    else if (a.y >= a.z)
      m.face = d.y >= 0.0 ? 2 : 3;
    else
      m.face = d.z >= 0.0 ? 4 : 5;
  }
  const dvec4 c = matrices[size_t(m.face)] * dvec4(p, 1.0);
  m.w = c.w;
  if (!(m.w > 0.0)) return m;  // at (or, for a spot, behind) the light centre
  const double u = c.x / m.w, v = c.y / m.w;
  m.sx = (u * 0.5 + 0.5) * size;
  m.sy = (0.5 - v * 0.5) * size;
  m.inside = std::fabs(u) <= 1.0 && std::fabs(v) <= 1.0;
  return m;
}

LightDepthMaps drawLightDepthMaps(const Scene& scene, const SceneTriangles& triangles,
                                  const Light& light, LightFrustums frustums, int size,
                                  Stats& stats, bool simd) {
  PassTimer timer(stats, "shadow map");
  LightDepthMaps maps;
  maps.size = size;
  const dvec3 centre(light.center);
  const Bounds3 bounds = scene.bounds();
  double far = 0.0;
  if (!bounds.empty()) {
    for (int corner = 0; corner < 8; ++corner) {
      const dvec3 q(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                    corner & 4 ? bounds.max.z : bounds.min.z);
      far = std::max(far, glm::length(q - centre));
    }
  }
  const float near_plane = far > 0.0 ? float(far * kNearFraction) : 1.0f;
  maps.near = double(near_plane);
  maps.centre = centre;

  std::vector<vec4> clip(triangles.vertex_count);
  ClipTriangles tris = triangles.triangles;
  Image<uint32_t> ids;  // rasterizeDepth's primitive ids, not needed here
  ids.resizeForOverwrite(size, size);
  for (const LightFace& face : frustums.faces) {
    const float fov = float(2.0 * std::atan(face.tan_half) * 180.0 / std::numbers::pi);
    // The target as far from the light as the scene reaches: lookAt's direction is the float
    // difference target - centre, which one unit away from a light 1e4 units out would be off
    // by some 1e-3 radians, more than a spot fitted around a distant scene spans.
    const dvec3 target = centre + face.axis * std::max(1.0, far);
    const View view =
        View::lookAt(size, size, light.center, vec3(target), vec3(face.up), fov, near_plane);
    // In double: a float view-projection holds the light's distance times the projection's
    // scale in its translation, and loses to cancellation what a distant light's narrow spot
    // needs (a light 1e5 units out lost whole shadows). Lookups use the same matrix.
    const dmat4 view_projection =
        dmat4(view.projection) * glm::lookAt(centre, target, dvec3(face.up));
    size_t base = 0;
    for (const Mesh& mesh : scene.meshes) {
      parallelFor((mesh.positions.size() + 4095) / 4096, [&](size_t chunk) {
        const size_t end = std::min(mesh.positions.size(), (chunk + 1) * 4096);
        for (size_t i = chunk * 4096; i < end; ++i)
          clip[base + i] = vec4(view_projection * dvec4(dvec3(mesh.positions[i]), 1.0));
      });
      base += mesh.positions.size();
    }
    tris.shared = clip.data();
    tris.shared_count = clip.size();
    Image<float>& depth = maps.depth.emplace_back();
    depth.resizeForOverwrite(size, size);
    rasterizeDepth(tris, depth, ids, stats, simd);
    maps.matrices.push_back(view_projection);
    // The projection's own scale (rounded to float), so texel sizes match what was drawn.
    maps.tan_half.push_back(1.0 / double(view.projection[1][1]));
  }
  maps.frustums = std::move(frustums);
  return maps;
}

}  // namespace penumbra
