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
#include "scene/scene.h"
#include "shadows/silhouette.h"
#include "shadows/technique.h"
#include "shadows/volume_options.h"

namespace penumbra {

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
};

// Fills the passes "silhouette" and "volumes" of `stats` and its counters.
Image<int32_t> shadowStencil(const Scene& scene, const vec3& centre, const View& view,
                             const EyeBuffers& eye, const ShadowStencilOptions& options,
                             Stats& stats);

// The hard shadow volume's answer for a point light at the light's centre: lit where the stencil
// is 0, unlit where the visible triangle faces away (facing_away.h), 1 on the background.
// Adds the pass "resolve".
TechniqueResult hardShadowVolumes(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, const ShadowStencilOptions& options);

}  // namespace penumbra
