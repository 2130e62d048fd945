#include "shadows/volume/shadow_stencil.h"

#include "core/timer.h"
#include "raster/rasterizer.h"
#include "shadows/caster_volume.h"
#include "shadows/facing_away.h"

namespace penumbra {
namespace {

// Side quads of every silhouette edge, extruded from the light centre to infinity, and with
// z-fail the caps. Payloads are signed weights of polygons facing out of the volume
// (rasterizer.h, rasterizeStencil).
void appendVolumePolygons(const Mesh& mesh, const vec3& centre, const View& view,
                          CasterVolume& volume, ClipTriangles& out) {
  appendExtrudedVertices(mesh, centre, view, volume, out);
  const uint32_t finite = volume.finite, infinite = volume.infinite;
  const uint8_t flags = volume.zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : volume.silhouette.edges) {
    // Quad (v1, v0, v0', v1') as two triangles sharing the diagonal v1-v0'.
    out.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
    out.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
  }
  // z-pass: caps are never in front of a visible point (volume_technique.cpp).
  if (!volume.zfail) return;
  forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
    out.add(a, b, c, weight, flags);
  });
}

}  // namespace

Image<int32_t> shadowStencil(const Scene& scene, const vec3& centre, const View& view,
                             const EyeBuffers& eye, const ShadowStencilOptions& options,
                             Stats& stats) {
  ClipTriangles polygons(eye.clip_vertices);
  {
    PassTimer timer(stats, "silhouette");
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      CasterVolume volume =
          casterVolume(scene, m, eye, centre, view, options.mode, options.policy);
      stats.silhouette_edges += volume.silhouette.edges.size();
      appendVolumePolygons(scene.meshes[m], centre, view, volume, polygons);
    }
  }
  Image<int32_t> stencil(view.width, view.height, 0);
  {
    PassTimer timer(stats, "volumes");
    StencilOptions stencil_options;
    stencil_options.simd = options.simd;
    stencil_options.two_level = options.two_level_stencil;
    rasterizeStencil(polygons, eye.depth, stencil, stats, stencil_options);
  }
  return stencil;
}

TechniqueResult hardShadowVolumes(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, const ShadowStencilOptions& options) {
  TechniqueResult result;
  const Image<int32_t> stencil =
      shadowStencil(scene, light.center, view, eye, options, result.stats);
  PassTimer timer(result.stats, "resolve");
  resolveVisibility(scene, light, view, eye, result.visibility,
                    [&](int x, int y) { return stencil.at(x, y) != 0 ? 0.0f : 1.0f; });
  return result;
}

}  // namespace penumbra
