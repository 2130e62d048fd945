#pragma once
// The caster-culling stage's counters (caster_culling.h), counted only when culling is on.
#include <vector>

#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kCastersTested{
    "casters_tested", "caster meshes tested against the light's receiver mask"};
inline constexpr CounterSpec kCastersCulled{
    "casters_culled", "of those, the ones whose shadow reaches no visible point: no volume, "
                      "wedge or potential edge built for them"};
inline constexpr CounterSpec kCulledCasterEdges{
    "culled_caster_edges", "edges of the culled casters, none of them looked at for silhouettes"};

// For the TechniqueInfo::counters of the techniques that cull.
inline std::vector<CounterSpec> casterCullingCounters() {
  return {kCastersTested, kCastersCulled, kCulledCasterEdges};
}

}  // namespace penumbra
