#include "core/simd_dispatch.h"

#include <cstdlib>
#include <cstring>

#ifndef PENUMBRA_SCALAR_ONLY
#include <hwy/highway.h>
#include <hwy/targets.h>
#endif

namespace penumbra {
namespace {

bool scalarForcedByEnvironment() {
  const char* value = std::getenv("PENUMBRA_SIMD");
  return value != nullptr && (std::strcmp(value, "off") == 0 || std::strcmp(value, "0") == 0);
}

}  // namespace

#ifndef PENUMBRA_SCALAR_ONLY

bool simdKernelsAvailable() {
  static const bool available = !scalarForcedByEnvironment();
  return available;
}

// Highway orders targets best-first by lowest bit; dispatch picks the best one compiled in.
const char* simdTargetName() {
  if (!simdKernelsAvailable()) return "scalar";
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return hwy::TargetName(targets & -targets);
}

#else

bool simdKernelsAvailable() { return false; }
const char* simdTargetName() { return "scalar"; }

#endif

}  // namespace penumbra
