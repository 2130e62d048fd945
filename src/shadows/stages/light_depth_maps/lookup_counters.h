#pragma once
// The counters of the shadow-map lookup stage (shadow_map_lookup.h): pixels whose point was
// looked up, and the ones a stencil-limited map skipped as outside the light's frustum (Arvo &
// Aila 2003; thesis section 4.2).
#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kShadowMapLookups{
    "shadow_map_lookups", "pixels whose point was looked up in a shadow map"};
inline constexpr CounterSpec kLookupsSaved{
    "lookups_saved", "pixels a stencil-limited shadow map skipped: outside the light frustum"};

}  // namespace penumbra
