#pragma once
// Heckbert and Herf's soft shadows (`heckbert-herf`; "Simulating Soft Shadows with Graphics
// Hardware", CMU-CS-97-104, 1997; the reference the 2002 wedge paper compares with): the
// average of N hard shadow volume renders, each from one stratified point on the light.
#include "shadows/heckbert_herf_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo heckbertHerfTechnique();

}  // namespace penumbra
