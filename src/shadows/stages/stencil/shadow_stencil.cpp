#include "shadows/stages/stencil/shadow_stencil.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "raster/rasterizer.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/stages/silhouettes/silhouette_layer.h"
#include "shadows/stages/stencil/stencil_resolve.h"

namespace penumbra {
namespace {

// True when the eye and `light` lie strictly on the same side of triangle t's plane (in double).
bool eyeOnCentreSide(const Mesh& mesh, size_t t, const dvec3& eye, const dvec3& light) {
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  const dvec3 n = glm::cross(b - a, c - a);
  const double e = glm::dot(n, eye - a), l = glm::dot(n, light - a);
  return (e > 0.0 && l > 0.0) || (e < 0.0 && l < 0.0);
}

// Side quads of every silhouette edge, extruded from the light centre to infinity, and with
// z-fail the caps. Payloads are signed weights of polygons facing out of the volume
// (rasterizer.h, rasterizeStencil).
//
// With skip_own_quads, a z-pass quad is not counted at the pixels of the triangles that use its
// edge (its owners, the first two) and have the eye and the light centre strictly on the same
// side of their plane: that plane holds the edge, so the quad, extruded away from the centre,
// lies wholly on the other side, and the segment from the eye to a point on the triangle's
// seen side cannot cross it. (A triangle seen from the side away from the centre is left out:
// the quad may lie on the eye's side, and a soft light can still reach the point.) Counting it
// anyway is a pure rounding decision: the quad leaves the visible surface along that very
// edge, and on a triangle nearly edge-on to the light (a terminator's, on a finely tessellated
// mesh) it runs within a hair of the whole triangle, so the float depth test flips pixel by
// pixel: z-fighting that darkens or lights those pixels against the ray-traced answer. z-fail
// quads count from behind the point, where they can lie: they keep the depth test.
// `edge_of`, when given, receives every polygon's scene edge (first_edge + the adjacency
// edge; kNoSceneEdge for a cap).
constexpr uint32_t kNoSceneEdge = 0xffffffffu;
void appendVolumePolygons(const Mesh& mesh, const EdgeAdjacency& adjacency, uint32_t first_id,
                          const vec3& centre, const View& view, bool skip_own_quads,
                          CasterVolume& volume, ClipTriangles& out, uint32_t first_edge,
                          std::vector<uint32_t>* edge_of) {
  appendExtrudedVertices(mesh, centre, view, volume, out);
  const dvec3 eye(view.eye), light(centre);
  const uint32_t finite = volume.finite, infinite = volume.infinite;
  const uint8_t flags = volume.zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : volume.silhouette.edges) {
    uint32_t owner[2] = {ClipTriangles::kNoOwner, ClipTriangles::kNoOwner};
    if (skip_own_quads && !volume.zfail) {
      const Edge& edge = adjacency.edges[e.edge];
      int owners = 0;
      for (uint32_t u = edge.first_use; u < edge.first_use + edge.use_count && owners < 2; ++u) {
        const uint32_t t = adjacency.uses[u].triangle;
        if (eyeOnCentreSide(mesh, t, eye, light)) owner[owners++] = first_id + t;
      }
    }
    // Quad (v1, v0, v0', v1') as two triangles sharing the diagonal v1-v0'.
    out.addOwned(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags, owner[0],
                 owner[1]);
    out.addOwned(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags,
                 owner[0], owner[1]);
    if (edge_of != nullptr) edge_of->insert(edge_of->end(), 2, first_edge + e.edge);
  }
  // z-pass: caps are never in front of a visible point (volume_technique.cpp).
  if (!volume.zfail) return;
  forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
    out.add(a, b, c, weight, flags);
    if (edge_of != nullptr) edge_of->push_back(kNoSceneEdge);
  });
}

}  // namespace

std::vector<uint32_t> sceneEdgeOffsets(const Scene& scene) {
  std::vector<uint32_t> offsets{0};
  for (const EdgeAdjacency& a : scene.adjacency)
    offsets.push_back(offsets.back() + uint32_t(a.edges.size()));
  return offsets;
}

Image<int32_t> shadowStencil(const Scene& scene, const vec3& centre, const View& view,
                             const EyeBuffers& eye, const ShadowStencilOptions& options,
                             Stats& stats) {
  ClipTriangles polygons(eye.clip_vertices);
  StencilQuads* quads = options.quads;
  std::vector<uint32_t> edge_of;  // per polygon, with `quads`
  const std::vector<uint32_t> edge_offsets =
      quads != nullptr ? sceneEdgeOffsets(scene) : std::vector<uint32_t>();
  if (quads != nullptr) quads->zfail.assign(scene.meshes.size(), 0);
  Image<float>* silhouette_layer = nullptr;
  Image<float>* culled_layer = nullptr;
  if (options.debug_layers != nullptr) {
    std::vector<DebugLayer>& layers = *options.debug_layers;
    debugLayer(layers, kSilhouetteEdgesLayer,
               "silhouette edges seen from the light centre, per pixel", view.width, view.height);
    debugLayer(layers, kCulledTilesLayer, "(volume polygon, culling tile) pairs culled, per pixel",
               view.width, view.height);
    // Pointers taken once both are in: adding a layer moves the others.
    silhouette_layer = &debugLayer(layers, kSilhouetteEdgesLayer, "", view.width, view.height);
    culled_layer = &debugLayer(layers, kCulledTilesLayer, "", view.width, view.height);
  }
  {
    PassTimer timer(stats, "silhouette");
    const std::vector<Silhouette>* known = options.known_silhouettes;
    PENUMBRA_CHECK(known == nullptr || known->size() == scene.meshes.size(),
                   "{} silhouettes kept for {} meshes", known ? known->size() : 0,
                   scene.meshes.size());
    std::vector<Silhouette>* found = known == nullptr ? options.found_silhouettes : nullptr;
    if (found != nullptr) found->assign(scene.meshes.size(), Silhouette{});
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      if (options.casting_meshes != nullptr && !(*options.casting_meshes)[m]) continue;
      if (options.caster_culling != nullptr && !options.caster_culling->mayShadow(m)) continue;
      const bool is_known = known != nullptr && (*known)[m].orientation.size() ==
                                                    scene.meshes[m].triangleCount();
      CasterVolume volume =
          is_known ? casterVolume(scene, m, (*known)[m], eye, centre, view, options.mode)
                   : casterVolume(scene, m, eye, centre, view, options.mode, options.policy);
      if (found != nullptr) (*found)[m] = volume.silhouette;
      stats.silhouette_edges += volume.silhouette.edges.size();
      if (silhouette_layer != nullptr)
        drawSilhouetteEdges(scene.meshes[m], volume.silhouette.edges, view, *silhouette_layer);
      if (quads != nullptr) quads->zfail[m] = volume.zfail ? 1 : 0;
      appendVolumePolygons(scene.meshes[m], scene.adjacency[m], scene.triangle_offsets[m],
                           centre, view, options.skip_own_quads, volume, polygons,
                           quads != nullptr ? edge_offsets[m] : 0,
                           quads != nullptr ? &edge_of : nullptr);
    }
  }
  Image<int32_t> stencil(view.width, view.height, 0);
  {
    PassTimer timer(stats, "volumes");
    StencilOptions stencil_options;
    stencil_options.simd = options.simd;
    stencil_options.two_level = options.two_level_stencil;
    if (options.skip_own_quads) stencil_options.primitive = &eye.primitive;
    stencil_options.culled_layer = culled_layer;
    std::vector<uint32_t> sources;
    std::vector<SetupTriangle> setup = setupTriangles(polygons, view.width, view.height,
                                                      quads != nullptr ? &sources : nullptr);
    stats.triangles += setup.size();
    rasterizeStencil(setup, eye.depth, stencil, stats, stencil_options);
    if (quads != nullptr) {
      // Group the pieces by scene edge (counting sort; caps are left out).
      quads->first.assign(edge_offsets.back() + 1, 0);
      for (const uint32_t source : sources)
        if (edge_of[source] != kNoSceneEdge) ++quads->first[edge_of[source] + 1];
      for (size_t e = 1; e < quads->first.size(); ++e) quads->first[e] += quads->first[e - 1];
      quads->pieces.assign(quads->first.back(), 0);
      std::vector<uint32_t> next(quads->first.begin(), quads->first.end() - 1);
      for (size_t k = 0; k < sources.size(); ++k) {
        const uint32_t edge = edge_of[sources[k]];
        if (edge != kNoSceneEdge) quads->pieces[next[edge]++] = uint32_t(k);
      }
      quads->setup = std::move(setup);
    }
  }
  return stencil;
}

TechniqueResult hardShadowVolumes(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, const ShadowStencilOptions& options,
                                  bool debug_layers) {
  TechniqueResult result;
  ShadowStencilOptions stencil_options = options;
  if (debug_layers) stencil_options.debug_layers = &result.debug_layers;
  const Image<int32_t> stencil =
      shadowStencil(scene, light.center, view, eye, stencil_options, result.stats);
  PassTimer timer(result.stats, "resolve");
  // resolveVisibility's rule with "lit where the stencil is 0", a row at a time.
  const FacingAway away(scene, light, view);
  result.visibility.resizeForOverwrite(view.width, view.height);
  constexpr int kRowsPerTask = 16;  // as shading's bands
  parallelFor(size_t((view.height + kRowsPerTask - 1) / kRowsPerTask), [&](size_t band) {
    const int y_end = std::min(view.height, int(band + 1) * kRowsPerTask);
    for (int y = int(band) * kRowsPerTask; y < y_end; ++y)
      resolveStencilRow(away, eye.primitive.row(y), stencil.row(y), result.visibility.row(y),
                        view.width, options.simd);
  });
  return result;
}

}  // namespace penumbra
