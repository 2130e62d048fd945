#pragma once
// Hard shadow volumes from the light centre (`volume`): z-pass (Heidmann) or z-fail (Everitt &
// Kilgard) into an integer stencil buffer; visibility is 1 where the count is 0, else 0.
#include "shadows/caster_volume.h"
#include "shadows/technique.h"

namespace penumbra {

struct VolumeOptions {
  VolumeMode mode = VolumeMode::Auto;
  // Polygons that cover a whole culling tile and pass its depth test everywhere add to one
  // coarse value per tile, not to each pixel: the z-min trivial accept of Aila's 2005 thesis
  // (section 1.5) feeding a two-level stencil (raster/tile_offsets.h). The stencil ends the same
  // bit for bit; false gives the papers' per-pixel passes.
  bool two_level_stencil = true;
};

TechniqueInfo volumeTechnique();

}  // namespace penumbra
