#include "render/frame.h"

#include <chrono>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "raster/eye_pass.h"
#include "raster/occlusion_culler.h"
#include "render/shading_kernel.h"
#include "render/shading_reuse.h"

namespace penumbra {

const char* occlusionCullingName(OcclusionCullingMode mode) {
  switch (mode) {
    case OcclusionCullingMode::Off: return "off";
    case OcclusionCullingMode::On: return "on";
    case OcclusionCullingMode::Auto: return "auto";
  }
  return "auto";
}

OcclusionCullingMode parseOcclusionCulling(const std::string& name) {
  for (const OcclusionCullingMode mode :
       {OcclusionCullingMode::Off, OcclusionCullingMode::On, OcclusionCullingMode::Auto})
    if (name == occlusionCullingName(mode)) return mode;
  throw Error(fmt::format("occlusion culling '{}' is not one of off, on, auto", name));
}

bool occlusionCulled(OcclusionCullingMode mode, const Scene& scene, int width, int height) {
  if (mode != OcclusionCullingMode::Auto) return mode == OcclusionCullingMode::On;
  // The culler's traversal and occluder pass cost about a pass over the pixels; what it saves
  // grows with the hidden triangles.
  return 2 * scene.triangleCount() >= size_t(width) * size_t(height);
}

FrameRenderer::~FrameRenderer() = default;

FrameRenderer::FrameRenderer(const Scene& scene, FrameOptions options)
    : scene_(scene), options_(std::move(options)) {
  ThreadLimit limit(options_.context.threads);
  const auto start = std::chrono::steady_clock::now();
  technique_ = prepareTechnique(options_.technique, scene_);
  shading_triangles_ = std::make_unique<ShadingTriangleTable>(scene_);
  const int width = options_.width > 0 ? options_.width : scene_.settings.width;
  const int height = options_.height > 0 ? options_.height : scene_.settings.height;
  if (occlusionCulled(options_.occlusion_culling, scene_, width, height))
    occlusion_ = std::make_unique<OcclusionCuller>(scene_);
  prepare_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void FrameRenderer::render(FrameResult& frame) const {
  const RenderContext& context = options_.context;
  ThreadLimit limit(context.threads);
  const int width = options_.width > 0 ? options_.width : scene_.settings.width;
  const int height = options_.height > 0 ? options_.height : scene_.settings.height;
  frame.view = scene_.camera.makeView(width, height);
  frame.eye_stats = Stats{};
  frame.total = Stats{};
  // The previous frame's buffers go first: alive while this frame allocates its own, they
  // would make the heap grow into fresh pages every frame (bench/README.md). The colour image is
  // kept and overwritten (shadeFrameInto).
  frame.eye = EyeBuffers{};
  frame.lights.clear();
  frame.eye = renderEyePass(scene_, frame.view, frame.eye_stats,
                            DepthPassOptions{.simd = context.simd,
                                             .delay_stream_bytes = options_.delay_stream_bytes,
                                             .depth_complexity = options_.depth_complexity},
                            occlusion_.get());
  frame.total.add(frame.eye_stats);
  frame.lights.reserve(scene_.lights.size());
  for (const Light& light : scene_.lights) {
    frame.lights.push_back(technique_->render(light, frame.view, frame.eye, context));
    frame.total.add(frame.lights.back().stats);
  }
  std::vector<const Image<float>*> visibility;
  std::vector<const ChannelVisibility*> channels;
  for (const TechniqueResult& r : frame.lights) {
    visibility.push_back(&r.visibility);
    channels.push_back(r.perChannel() ? &r.channels : nullptr);
  }
  {
    PassTimer timer(frame.total, "shade");
    shadeFrameInto(scene_, frame.view, frame.eye, visibility, frame.color, context.simd,
                   channels, shading_triangles_.get());
  }
}

FrameResult renderFrame(const Scene& scene, const FrameOptions& options) {
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  renderer.render(frame);
  frame.total.time_ms.insert(frame.total.time_ms.begin(), {"prepare", renderer.prepareMs()});
  return frame;
}

}  // namespace penumbra
