#include "shadows/mask/mask_volumes.h"

#include <numeric>

#include "core/timer.h"
#include "scene/connected_parts.h"
#include "shadows/stages/caster_volumes/caster_volume.h"

namespace penumbra {

namespace {

// The caster's volume polygons as shadow_stencil.cpp draws them (without its owners, which
// `volume` does not use): side quads (v1, v0, v0', v1') from the light centre to infinity, and
// with z-fail the caps; with each polygon's connected part in `part_of_polygon`.
ClipTriangles casterPolygons(const Mesh& mesh, const vec3& centre, const View& view,
                             const EyeBuffers& eye, CasterVolume& volume,
                             const std::vector<uint32_t>& part_of_vertex,
                             std::vector<uint32_t>& part_of_polygon) {
  ClipTriangles polygons(eye.clip_vertices);
  appendExtrudedVertices(mesh, centre, view, volume, polygons);
  const uint32_t finite = volume.finite, infinite = volume.infinite;
  const uint8_t flags = volume.zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : volume.silhouette.edges) {
    polygons.add(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags);
    polygons.add(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags);
    part_of_polygon.insert(part_of_polygon.end(), 2, part_of_vertex[e.v0]);
  }
  if (volume.zfail) {
    forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
      polygons.add(a, b, c, weight, flags);
      part_of_polygon.push_back(part_of_vertex[a < infinite ? a - finite : a - infinite]);
    });
  }
  return polygons;
}

}  // namespace

MaskVolumes maskVolumes(const Scene& scene, const vec3& centre, const View& view,
                        const EyeBuffers& eye, VolumeMode mode, Stats& stats,
                        const CasterCulling* caster_culling) {
  PassTimer timer(stats, "silhouette");
  MaskVolumes out;
  std::vector<uint32_t> part_of_vertex, part_of_polygon, sources, first_of_part;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (caster_culling != nullptr && !caster_culling->mayShadow(m)) continue;
    const Mesh& mesh = scene.meshes[m];
    CasterVolume volume = casterVolume(scene, m, eye, centre, view, mode, CasterPolicy::Auto);
    stats.silhouette_edges += volume.silhouette.edges.size();
    // A light inside a closed caster has no silhouette from its centre, but the caps of the
    // z-fail volume still enclose everything outside the caster: only z-pass has nothing to draw.
    if (volume.silhouette.edges.empty() && !volume.zfail) continue;
    const uint32_t parts = connectedParts(mesh, part_of_vertex);
    part_of_polygon.clear();
    const ClipTriangles polygons =
        casterPolygons(mesh, centre, view, eye, volume, part_of_vertex, part_of_polygon);
    const std::vector<SetupTriangle> setup =
        setupTriangles(polygons, view.width, view.height, &sources);
    stats.triangles += setup.size();
    // One volume per part, each keeping the caster's drawing order (a counting sort by part).
    first_of_part.assign(size_t(parts) + 1, 0);
    for (const uint32_t s : sources) ++first_of_part[part_of_polygon[s] + 1];
    std::partial_sum(first_of_part.begin(), first_of_part.end(), first_of_part.begin());
    const size_t base = out.setup.size();
    const uint32_t first_volume = uint32_t(out.caster_of.size());
    out.setup.resize(base + setup.size());
    out.volume_of.resize(base + setup.size());
    for (size_t i = 0; i < setup.size(); ++i) {
      const uint32_t part = part_of_polygon[sources[i]];
      const size_t at = base + first_of_part[part]++;
      out.setup[at] = setup[i];
      out.volume_of[at] = first_volume + part;
    }
    out.caster_of.insert(out.caster_of.end(), parts, uint32_t(m));
  }
  return out;
}

}  // namespace penumbra
