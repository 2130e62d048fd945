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
// `stats`. With `occlusion` (a culler made for this scene, raster/occlusion_culler.h), only the
// triangles it cannot prove hidden are drawn; every buffer is bit-identical to the pass without
// it, clip_vertices included.
class OcclusionCuller;
EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats, bool simd = true,
                         OcclusionCuller* occlusion = nullptr);
// The same with the depth pass's options: a delay stream (raster/delay_stream.h) among the
// triangles that reach the rasterizer, which leaves the buffers as they are, and its counters.
EyeBuffers renderEyePass(const Scene& scene, const View& view, Stats& stats,
                         const DepthPassOptions& options, OcclusionCuller* occlusion = nullptr);

}  // namespace penumbra
