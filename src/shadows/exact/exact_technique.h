#pragma once
// Exact soft shadow volumes (`exact`): the visibility of a spherical light's fixed sample set
// from every visible point, counted without rays from the silhouette edges seen from that point
// and the hard shadow volume's count at the light centre (Laine, Aila, Assarsson, Lehtinen and
// Akenine-Moller, "Soft Shadow Volumes for Ray Tracing", 2005; docs/exact-soft-shadows.md).
#include "shadows/exact_options.h"
#include "shadows/technique.h"

namespace penumbra {

TechniqueInfo exactTechnique();

}  // namespace penumbra
