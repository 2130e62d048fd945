#pragma once
// Whether a hot loop runs its SIMD version or its scalar twin. Every kernel dispatcher asks
// useSimd(requested) instead of reading its `simd` argument alone, so that one switch sends the
// whole program down the scalar twins: the build option PENUMBRA_SCALAR_ONLY (no SIMD compiled)
// or, in any build, the environment variable PENUMBRA_SIMD=off, read once at the first kernel
// call. CI runs the test suite a second time with PENUMBRA_SIMD=off instead of compiling a
// scalar-only build: the same scalar code is exercised for a third of the build time.

namespace penumbra {

// False in a PENUMBRA_SCALAR_ONLY build and when PENUMBRA_SIMD is "off" or "0".
bool simdKernelsAvailable();
// Name of the SIMD target chosen at run time (e.g. "AVX2"), or "scalar".
const char* simdTargetName();

inline bool useSimd(bool requested) { return requested && simdKernelsAvailable(); }

}  // namespace penumbra
