#pragma once
// The hard shadow volume's stencil for one point light: per pixel, the signed count of shadow
// volumes that contain the visible point (volume_technique.cpp says how z-pass and z-fail count).
// Shared by the hard volumes (`volume`), which test it against zero, and the exact soft shadow
// volumes (`exact`), which take it with two-sided casters as the number of triangles the segment
// from the light centre to the point crosses (silhouette.h).
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/silhouettes/silhouette.h"
#include "shadows/technique.h"
#include "shadows/volume_options.h"

namespace penumbra {

// The volume polygons as the stencil pass set them up, for a pass that must know what the
// stencil decided at a pixel (exact_technique.cpp, with rasterizer.h's stencilContributionAt):
// per scene edge (the edges of Scene::adjacency numbered mesh after mesh, from
// sceneEdgeOffsets) the set-up pieces of its quad, and per mesh whether its volume was z-fail.
struct StencilQuads {
  std::vector<SetupTriangle> setup;  // every polygon drawn, quads and caps
  std::vector<uint32_t> first;       // per scene edge, then the end: into `pieces`
  std::vector<uint32_t> pieces;      // indices into `setup`, grouped by scene edge
  std::vector<uint8_t> zfail;        // per mesh (0 for a mesh that casts nothing)
};
// The first scene-edge number of every mesh, then the total.
std::vector<uint32_t> sceneEdgeOffsets(const Scene& scene);

struct ShadowStencilOptions {
  VolumeMode mode = VolumeMode::Auto;
  CasterPolicy policy = CasterPolicy::Auto;
  bool two_level_stencil = true;
  bool simd = true;
  // z-pass quads are not counted at the pixels of the triangles that use their edge and face
  // the light centre from the eye's side (shadow_stencil.cpp says why). The hard volumes and
  // the wedges keep the depth test (their images are compared bit for bit); exact needs it.
  bool skip_own_quads = false;
  // Per mesh, whether it casts (null: every mesh): the soft techniques' second pass over the
  // open meshes' other facing draws only those meshes (silhouette.h).
  const std::vector<uint8_t>* casting_meshes = nullptr;
  // When set, the meshes it culls (caster_culling.h) get no silhouette and no volume.
  const CasterCulling* caster_culling = nullptr;
  // When set, receives the polygons as set up (StencilQuads).
  StencilQuads* quads = nullptr;
  // When set, one per mesh: the meshes' silhouettes from the centre with `policy`
  // (findSilhouette), kept by a caller whose light has not moved, used instead of finding them;
  // an entry with no orientation for a mesh with triangles (one culled when it was found) is
  // found again.
  const std::vector<Silhouette>* known_silhouettes = nullptr;
  // When set (and known_silhouettes is not), receives the silhouettes found, one per mesh (empty
  // for a mesh that casts nothing or was culled).
  std::vector<Silhouette>* found_silhouettes = nullptr;
  // When set, the debug layers of the silhouettes (kSilhouetteEdgesLayer) and of the tile
  // culling (kCulledTilesLayer) are added to it (shadows/technique.h).
  std::vector<DebugLayer>* debug_layers = nullptr;
};

// Fills the passes "silhouette" and "volumes" of `stats` and its counters.
Image<int32_t> shadowStencil(const Scene& scene, const vec3& centre, const View& view,
                             const EyeBuffers& eye, const ShadowStencilOptions& options,
                             Stats& stats);

// The hard shadow volume's answer for a point light at the light's centre: lit where the stencil
// is 0, unlit where the visible triangle faces away (facing_away.h), 1 on the background.
// Adds the pass "resolve". With `debug_layers` (RenderContext::debug_layers), the stencil's
// layers go into the result's debug_layers.
TechniqueResult hardShadowVolumes(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, const ShadowStencilOptions& options,
                                  bool debug_layers = false);

}  // namespace penumbra
