#pragma once
#include "shadows/technique.h"

namespace penumbra {

// The oracle: ray-traced visibility with Embree from every pixel's visible point (found from
// the eye pass's depth buffer, so every technique is judged on the same points).
TechniqueResult renderReference(const TechniqueOptions& options, const Scene& scene,
                                const Light& light, const View& view, const EyeBuffers& eye);

}  // namespace penumbra
