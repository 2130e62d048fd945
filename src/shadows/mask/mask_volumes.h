#pragma once
// The shadow volume polygons the masks draw, caster by caster: the very quads and caps of the
// hard volumes (`volume`, shadow_stencil.cpp; caster_volume.h), set up for the rasterizer, with
// the caster each came from. The mask's blends do not commute the way the stencil's additions
// do, so the paper draws one volume at a time, front faces first (section 4.2): the rasterizer
// needs to know where one volume ends.
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/volume_options.h"

namespace penumbra {

struct MaskVolumes {
  std::vector<SetupTriangle> setup;  // volume after volume, each in the order `volume` draws it
  std::vector<uint32_t> volume_of;   // per set-up triangle, its caster (scene mesh index)
};

// Counts silhouette_edges and triangles; adds the pass "silhouette".
MaskVolumes maskVolumes(const Scene& scene, const vec3& centre, const View& view,
                        const EyeBuffers& eye, VolumeMode mode, Stats& stats);

}  // namespace penumbra
