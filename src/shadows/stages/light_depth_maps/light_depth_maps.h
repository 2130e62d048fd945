#pragma once
// The shadow map itself: the scene's depth seen from the light centre through each face of its
// LightFrustums, drawn by the eye pass's rasterizer (rasterizeDepth: tiled, multithreaded,
// reversed-Z), and the projection of a world point into it. Shared by `shadow-map` and `pcss`.
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/triangle_setup.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/stages/light_depth_maps/light_frustum.h"

namespace penumbra {

// Every triangle of the scene, mesh after mesh, as indices into its vertices (mesh after mesh):
// prepared once per scene, the faces only change the clip-space vertices.
struct SceneTriangles {
  explicit SceneTriangles(const Scene& scene);
  ClipTriangles triangles;
  size_t vertex_count = 0;
};

// Where a world point lands in the map.
struct MapPoint {
  int face = 0;
  double sx = 0, sy = 0;  // texel coordinates, texel (i, j) covers [i, i+1) x [j, j+1)
  double w = 0;           // distance from the light centre along the face's axis
  bool inside = false;    // in front of the light and within the face's frustum
};

struct LightDepthMaps {
  LightFrustums frustums;
  dvec3 centre{0.0};                 // the light centre, which every face looks from
  std::vector<dmat4> matrices;       // per face: the view-projection it was drawn with (double)
  std::vector<double> tan_half;      // the tangent of each face's half angle, as projected
  std::vector<Image<float>> depth;   // per face: near / distance of the nearest occluder, 0: none
  int size = 0;                      // texels along each side of each face
  double near = 1.0;                 // every face's near plane

  // The face of p's major axis for a cube (the first on a tie: p then projects inside it), the
  // spot otherwise.
  MapPoint project(const dvec3& p) const;
  // World size of one texel at distance w along a face's axis.
  double texelSize(int face, double w) const { return 2.0 * w * tan_half[size_t(face)] / size; }
  // Distance of the occluder stored at texel (i, j), clamped to the face; +infinity where
  // nothing was drawn. Lookups past a face's border are clamped to its edge texels instead of
  // continuing on the neighbouring face, an approximation that only matters for kernels
  // straddling a cube edge.
  double occluder(int face, int i, int j) const {
    const float stored = depth[size_t(face)].at(std::clamp(i, 0, size - 1),
                                                 std::clamp(j, 0, size - 1));
    return stored == 0.0f ? INFINITY : near / double(stored);
  }
};

// Draws the maps for `light` (pass "shadow map" of `stats`: pixels_rasterized, z_reads,
// stencil_writes as depth writes, triangles).
LightDepthMaps drawLightDepthMaps(const Scene& scene, const SceneTriangles& triangles,
                                  const Light& light, LightFrustums frustums, int size,
                                  Stats& stats, bool simd);

}  // namespace penumbra
