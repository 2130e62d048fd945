#pragma once
#include "shadows/technique.h"

namespace penumbra {

// Hard shadow volumes from the light centre: z-pass (Heidmann) or z-fail (Everitt & Kilgard)
// into an integer stencil buffer; visibility is 1 where the count is 0, else 0.
TechniqueResult renderShadowVolume(const TechniqueOptions& options, const Scene& scene,
                                   const Light& light, const View& view, const EyeBuffers& eye);

}  // namespace penumbra
