#pragma once
// Percentage-closer soft shadows (`pcss`, Fernando 2005): a blocker search in the shadow map,
// a penumbra width estimated from the light's size and the blocker and receiver distances, and
// percentage-closer filtering over that width.
#include "shadows/pcss_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo pcssTechnique();

}  // namespace penumbra
