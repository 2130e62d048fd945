#pragma once
// The alias-free shadow map (`alias-free`): the eye pass's visible samples are placed in the
// light's image plane at their exact positions, and every occluder triangle is tested against
// the samples it covers there (an irregular z-buffer; Aila & Laine, "Alias-Free Shadow Maps",
// EGSR 2004; Aila's 2005 thesis, section 4.1; docs/alias-free-shadow-maps.md).
#include "shadows/alias_free_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo aliasFreeTechnique();

}  // namespace penumbra
