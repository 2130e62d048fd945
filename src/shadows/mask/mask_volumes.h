#pragma once
// The shadow volume polygons the masks draw: the very quads and caps of the hard volumes
// (`volume`, shadow_stencil.cpp; caster_volume.h), set up for the rasterizer, one volume per
// connected part of each caster. The mask's blends do not commute the way the stencil's
// additions do, so the paper draws one volume at a time (section 4.2): the rasterizer needs to
// know where one volume ends. Penumbra splits a caster into its connected parts (triangles
// sharing vertices) because each part's volume is closed by itself and counts its own shadow
// (>= 0 everywhere for a closed part), while the whole caster's volume is entered by an eye ray
// once per part it passes: a grid of boxes or a multi-part model would need headroom the 8 bits
// lack (docs/reproducing-hsv-and-masks.md).
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/volume_options.h"

namespace penumbra {

struct MaskVolumes {
  std::vector<SetupTriangle> setup;  // volume after volume, each in the order `volume` draws it
  std::vector<uint32_t> volume_of;   // per set-up triangle, its volume
  std::vector<uint32_t> caster_of;   // per volume, its caster (scene mesh index)
};

// Counts silhouette_edges and triangles; adds the pass "silhouette". A caster `caster_culling`
// culls gets no volume.
MaskVolumes maskVolumes(const Scene& scene, const vec3& centre, const View& view,
                        const EyeBuffers& eye, VolumeMode mode, Stats& stats,
                        const CasterCulling* caster_culling = nullptr);

}  // namespace penumbra
