#pragma once
// Coverage soft shadow volumes (`coverage`): Assarsson and Akenine-Moller's 2003 algorithm
// ("A Geometry-based Soft Shadow Volume Algorithm using Graphics Hardware", SIGGRAPH 2003), as
// Funk's 2004 report describes and implements it, for sphere, disk and rectangle lights.
#include "shadows/coverage_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo coverageTechnique();

}  // namespace penumbra
