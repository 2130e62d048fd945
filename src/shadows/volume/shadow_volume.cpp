// Hard shadow volumes (Crow 1977) counted in an integer stencil buffer: z-pass (Heidmann 1991)
// or z-fail (Everitt & Kilgard 2002), as reviewed in the 2004 paper, sections 2 and 5, and in
// the 2005 thesis, section 2.2.
//
// z-pass counts volume polygons strictly in front of the visible point, front faces +, back
// faces -; it needs no caps because a light cap in front of the point would be an opaque
// triangle hiding it, and dark caps lie at infinity. z-fail counts polygons behind the point or
// at its depth, back faces +, front faces -, caps included. A light cap coinciding with the
// visible surface (bit-identical depth, volume_geometry.h) is thus counted by z-fail, which is
// what makes a point on a triangle's unlit side come out shadowed. With the eye outside every
// volume both counts are equal, since each closed volume's polygons sum to zero along a ray.
#include "shadows/volume/shadow_volume.h"

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/rasterizer.h"
#include "shadows/facing_away.h"
#include "shadows/silhouette.h"
#include "shadows/volume/volume_geometry.h"
#include "shadows/volume/volume_mode.h"

namespace penumbra {

TechniqueResult renderShadowVolume(const TechniqueOptions& options, const Scene& scene,
                                   const Light& light, const View& view, const EyeBuffers& eye) {
  TechniqueResult result;
  Stats& stats = result.stats;
  ClipTriangles polygons;
  {
    PassTimer timer(stats, "silhouette");
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      const Mesh& mesh = scene.meshes[m];
      const Silhouette silhouette = findSilhouette(mesh, scene.adjacency[m], light.center);
      stats.silhouette_edges += silhouette.edges.size();
      const bool zfail =
          options.volume_mode == VolumeMode::ZFail ||
          (options.volume_mode == VolumeMode::Auto &&
           mayContainNearPlane(view, light.center, mesh.bounds()));
      appendVolumePolygons(mesh, silhouette, light.center, view, zfail, polygons);
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
  {
    PassTimer timer(stats, "resolve");
    resolveVisibility(scene, light, view, eye, result.visibility,
                      [&](int x, int y) { return stencil.at(x, y) != 0 ? 0.0f : 1.0f; });
  }
  return result;
}

}  // namespace penumbra
