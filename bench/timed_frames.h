#pragma once
// The benchmark loop of a warm frame: a FrameRenderer (technique prepared once) rendering into
// one reused FrameResult, as a viewer renders frame after frame.
#include <benchmark/benchmark.h>

#include "render/frame.h"

namespace penumbra {

// Runs the loop, timed by hand: fps is frames per wall-clock second (the library's rate
// counters divide by the main thread's CPU time). Sets the counters fps, frame_ms, one
// "<pass>_ms" per pass (mean over the frames, in the order passes first appear) and threads.
// Returns false when no time was measured (then no counters are set).
bool timeWarmFrames(benchmark::State& state, const FrameRenderer& renderer, FrameResult& frame);

}  // namespace penumbra
