#pragma once
// Hard shadow volumes drawn volume by volume with fewer pixels than `volume`, the same image:
// `depth-bounds-volume` (thesis section 2.2, the depth-bounds baseline) and
// `hierarchical-volume` (thesis section 4.3, publication P2). tiled_volume_stencil.h says how.
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo depthBoundsVolumeTechnique();
TechniqueInfo hierarchicalVolumeTechnique();

}  // namespace penumbra
