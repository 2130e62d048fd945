#pragma once
// The benchmark loop of a warm frame: a FrameRenderer (technique prepared once) rendering into
// one reused FrameResult, as a viewer renders frame after frame.
#include <benchmark/benchmark.h>

#include "render/frame.h"
#include "shadows/technique.h"

namespace penumbra {

// Google Benchmark runs a benchmark's function anew for its warm-up and for each measured
// run, so a technique prepared inside it starts cold every time: buffers a prepared technique
// keeps for the next render (alias-free's samples, tens of megabytes at 1920 x 1080) would be
// allocated, and page-faulted in, inside the one or two timed iterations a slow technique gets.
// A frame loop pays that once, so the benchmarks render one untimed frame first: with
// renderUntimed, or inside timeWarmFrames.
void renderUntimed(const PreparedTechnique& technique, const Scene& scene, const View& view,
                   const EyeBuffers& eye);

// Runs the loop (after one untimed frame), timed by hand: fps is frames per wall-clock second (the
// library's rate counters divide by the main thread's CPU time). Sets the counters fps, frame_ms,
// one "<pass>_ms" per pass (mean over the frames, in the order passes first appear) and threads.
// Returns false when no time was measured (then no counters are set).
bool timeWarmFrames(benchmark::State& state, const FrameRenderer& renderer, FrameResult& frame);

}  // namespace penumbra
