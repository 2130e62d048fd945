#pragma once
// The standard shadow map (`shadow-map`, Williams 1978): depth from the light centre into a cube
// map of six faces, compared with each visible point's distance, with constant and slope-scaled
// bias and percentage-closer filtering (Reeves, Salesin & Cook 1987).
#include "shadows/shadow_map_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo shadowMapTechnique();

}  // namespace penumbra
