#include "shadows/mask/mask_volumes.h"

#include "core/timer.h"
#include "shadows/stages/caster_volumes/caster_volume.h"

namespace penumbra {

MaskVolumes maskVolumes(const Scene& scene, const vec3& centre, const View& view,
                        const EyeBuffers& eye, VolumeMode mode, Stats& stats) {
  PassTimer timer(stats, "silhouette");
  MaskVolumes out;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    CasterVolume volume = casterVolume(scene, m, eye, centre, view, mode, CasterPolicy::Auto);
    stats.silhouette_edges += volume.silhouette.edges.size();
    // A light inside a closed caster has no silhouette from its centre, but the caps of the
    // z-fail volume still enclose everything outside the caster: only z-pass has nothing to draw.
    if (volume.silhouette.edges.empty() && !volume.zfail) continue;
    // As shadow_stencil.cpp draws them (without its owners, which `volume` does not use):
    // side quads (v1, v0, v0', v1') from the light centre to infinity, and with z-fail the caps.
    ClipTriangles polygons(eye.clip_vertices);
    appendExtrudedVertices(mesh, centre, view, volume, polygons);
    const uint32_t finite = volume.finite, infinite = volume.infinite;
    const uint8_t flags = volume.zfail ? kZFail : 0;
    for (const SilhouetteEdge& e : volume.silhouette.edges) {
      polygons.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
      polygons.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
    }
    if (volume.zfail) {
      forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
        polygons.add(a, b, c, weight, flags);
      });
    }
    const std::vector<SetupTriangle> setup = setupTriangles(polygons, view.width, view.height);
    stats.triangles += setup.size();
    out.setup.insert(out.setup.end(), setup.begin(), setup.end());
    out.volume_of.insert(out.volume_of.end(), setup.size(), uint32_t(m));
  }
  return out;
}

}  // namespace penumbra
