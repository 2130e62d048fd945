#include "shadows/hierarchical/volume_set.h"

#include <algorithm>

#include "core/timer.h"
#include "shadows/caster_volume.h"

namespace penumbra {

ShadowVolumeSet buildShadowVolumes(const Scene& scene, const vec3& centre, const View& view,
                                   const EyeBuffers& eye, VolumeMode mode, Stats& stats) {
  PassTimer timer(stats, "silhouette");
  ShadowVolumeSet set;
  set.begin.push_back(0);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    CasterVolume volume =
        casterVolume(scene, m, eye, centre, view, mode, CasterPolicy::Auto);
    stats.silhouette_edges += volume.silhouette.edges.size();
    // The same polygons, in the same order and vertex order, as the per-pixel stencil's
    // (shadow_stencil.cpp), so every pixel a volume polygon reaches gets bit-identical edge
    // and depth values.
    ClipTriangles polygons(eye.clip_vertices);
    appendExtrudedVertices(mesh, centre, view, volume, polygons);
    const uint32_t finite = volume.finite, infinite = volume.infinite;
    const uint8_t flags = volume.zfail ? kZFail : 0;
    for (const SilhouetteEdge& e : volume.silhouette.edges) {
      polygons.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
      polygons.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
    }
    forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
      if (volume.zfail) {
        polygons.add(a, b, c, weight, flags);
      } else if (a < infinite) {
        // z-pass: only the light cap, to be classified; the dark cap lies at depth 0, behind
        // every surface, where z-pass never counts and no tile's box reaches.
        polygons.add(a, b, c, weight, flags | kClassifyOnly);
      }
    });
    std::vector<SetupTriangle> setup = setupTriangles(polygons, view.width, view.height);
    stats.triangles += setup.size();
    float lo = 1.0f, hi = 0.0f;
    for (const SetupTriangle& t : setup) {
      if (t.flags & kClassifyOnly) continue;
      lo = std::min(lo, t.depth_min);
      hi = std::max(hi, t.depth_max);
    }
    set.triangles.insert(set.triangles.end(), setup.begin(), setup.end());
    set.begin.push_back(uint32_t(set.triangles.size()));
    set.zfail.push_back(volume.zfail);
    set.may_contain_eye.push_back(mayContainNearPlane(view, centre, mesh.bounds()));
    set.depth_min.push_back(lo);
    set.depth_max.push_back(hi);
  }
  return set;
}

}  // namespace penumbra
