#pragma once
// alias-free's own counters (Aila & Laine 2004; thesis section 4.1).
#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kLightSamples{
    "light_samples", "eye samples placed in the light's irregular z-buffer (alias-free)"};
inline constexpr CounterSpec kSampleTests{
    "sample_tests", "(occluder triangle, light-space sample) pairs tested (alias-free)"};

}  // namespace penumbra
