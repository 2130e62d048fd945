#pragma once
// The technique table: every technique that ships with Penumbra (technique_table.cpp).
#include <vector>

#include "shadows/technique.h"

namespace penumbra {

std::vector<TechniqueInfo> builtinTechniques();

}  // namespace penumbra
