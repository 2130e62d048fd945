#pragma once
// Shadow masks without a stencil buffer (Roettger, Irion and Ertl 2002): `mask-alpha` keeps the
// mask in the alpha channel, `mask-colour` in the colour (screen) buffer's RGB. Hard shadows
// from the light centre, the same volumes as `volume`; visibility 1 where the normalised mask
// says lit, else 0; with --mask-scale 2 or 4 the mask is computed at that fraction of the
// resolution and bilinearly magnified (section 4.5), visibility then in [0, 1].
#include "shadows/mask/mask_values.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo maskTechnique(MaskChannel channel);

}  // namespace penumbra
