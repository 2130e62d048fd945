#pragma once
// The oracle (`reference`): ray-traced visibility with Embree from every pixel's visible point,
// found from the eye pass's depth buffer, so every technique is judged on the same points.
#include "shadows/reference_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo referenceTechnique();

}  // namespace penumbra
