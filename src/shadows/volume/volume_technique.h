#pragma once
// Hard shadow volumes from the light centre (`volume`): z-pass (Heidmann) or z-fail (Everitt &
// Kilgard) into an integer stencil buffer; visibility is 1 where the count is 0, else 0.
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/technique.h"
#include "shadows/volume_options.h"

namespace penumbra {

TechniqueInfo volumeTechnique();

}  // namespace penumbra
