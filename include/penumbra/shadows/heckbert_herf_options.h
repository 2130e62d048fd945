#pragma once
// Options of the Heckbert-Herf average of hard shadows (`heckbert-herf`). For typed access:
//   config.options<penumbra::HeckbertHerfOptions>().samples = 64;
#include <cstdint>

namespace penumbra {

struct HeckbertHerfOptions {
  // Hard shadow volume renders averaged, one per stratified point on the light (4..1024).
  int samples = 16;
  uint64_t seed = 1;  // of the jitter inside the strata (light_sampling.h, fixedSamples)
};

}  // namespace penumbra
