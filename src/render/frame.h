#pragma once
// One frame: the eye pass, a shadow technique per light, shading (DESIGN.md data flow).
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"
#include "shadows/technique.h"

namespace penumbra {

struct FrameOptions {
  TechniqueOptions technique;
  int width = 0;    // 0: the scene's settings
  int height = 0;
  int threads = 0;  // 0: all cores
};

struct FrameResult {
  View view;
  EyeBuffers eye;
  Stats eye_stats;                       // the eye pass
  std::vector<TechniqueResult> lights;   // one per Scene::lights entry, same order
  Image<vec3> color;                     // linear RGB, shaded (render/shading.h)
  Stats total;                           // eye pass + every light's technique + shading time
};

FrameResult renderFrame(const Scene& scene, const FrameOptions& options);

// The same frame into `frame`, for loops that render frame after frame (a viewer, a benchmark):
// every field is overwritten, and the colour image keeps its memory when the size is unchanged,
// so a frame does not pay for allocating and page-faulting a new full-size image.
void renderFrame(const Scene& scene, const FrameOptions& options, FrameResult& frame);

}  // namespace penumbra
