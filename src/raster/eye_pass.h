#pragma once
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/depth_pass.h"
#include "scene/scene.h"

namespace penumbra {

// Rasterizes every triangle of the scene from the eye: depth (reversed-Z, infinite far plane),
// per-tile z-min/z-max and the visible triangle of every pixel. Every triangle is drawn
// two-sided (see eye_pass.cpp for why not even closed meshes are culled). Counters go to
// `stats`.
EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats, bool simd = true);
// The same with the depth pass's options: a delay stream (raster/delay_stream.h), which leaves
// the buffers as they are, and its counters.
EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats,
                         const DepthPassOptions& options);

}  // namespace penumbra
