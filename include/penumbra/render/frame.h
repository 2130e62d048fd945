#pragma once
// One frame: the eye pass, a shadow technique per light, shading (README, Architecture).
#include <cstddef>
#include <memory>
#include <vector>

#include <penumbra/core/image.h>
#include <penumbra/core/stats.h>
#include <penumbra/core/view.h>
#include <penumbra/raster/depth_buffer.h>
#include <penumbra/scene/scene.h>
#include <penumbra/shadows/technique.h>

namespace penumbra {

// Off, on, or on where it pays (the culler's own pass costs more than it saves where little is
// hidden in few triangles: docs/occlusion-culling.md, "Measured").
enum class OcclusionCullingMode { Off, On, Auto };
// "off", "on", "auto", as `penumbra render --occlusion-culling` and the stats JSON name them.
const char* occlusionCullingName(OcclusionCullingMode mode);
// The mode of a name above; throws penumbra::Error naming the text and the choices.
OcclusionCullingMode parseOcclusionCulling(const std::string& name);

struct FrameOptions {
  TechniqueConfig technique;  // the technique and its own options
  int width = 0;              // 0: the scene's settings
  int height = 0;
  RenderContext context;      // threads, SIMD, progress: every pass obeys them
  // The eye pass's delay stream (delayed occlusion culling, Aila's 2005 thesis, section 5.1):
  // its ring in bytes, 0 for none. The eye buffers are the same with any ring; only the work
  // and the eye pass's counters change (docs/reproducing-visibility.md).
  size_t delay_stream_bytes = 0;
  // Count the eye pass's depth complexity (eye_depth_passes, eye_covered_pixels); always
  // counted with a delay stream.
  bool depth_complexity = false;
  // Object-level occlusion culling in the eye pass (docs/occlusion-culling.md): hidden objects
  // are not rasterized. Every output is bit-identical in every mode; only the eye pass's work
  // and counters change. Auto culls where the scene has at least half as many triangles as the
  // frame has pixels (occlusionCulled).
  OcclusionCullingMode occlusion_culling = OcclusionCullingMode::Auto;
};

struct FrameResult {
  View view;
  EyeBuffers eye;
  Stats eye_stats;                       // the eye pass
  std::vector<TechniqueResult> lights;   // one per Scene::lights entry, same order
  Image<vec3> color;                     // linear RGB, shaded (render/shading.h)
  Stats total;                           // eye pass + every light's technique + shading time
};

// Renders frame after frame of one scene with one technique, prepared once (per-scene state
// such as the oracle's BVH: shadows/technique.h). The scene must outlive the renderer and stay
// unchanged.
// Whether `mode` culls frames of `scene` at width x height.
bool occlusionCulled(OcclusionCullingMode mode, const Scene& scene, int width, int height);

class ShadingTriangleTable;
class OcclusionCuller;

class FrameRenderer {
 public:
  FrameRenderer(const Scene& scene, FrameOptions options);
  ~FrameRenderer();
  // Overwrites every field of `frame`; the colour image keeps its memory when the size is
  // unchanged, so a frame does not pay for allocating and page-faulting a new image. With
  // occlusion culling the objects visible in one frame are the first occluders of the next, so
  // frames of one renderer must not be rendered at once from several threads.
  void render(FrameResult& frame) const;
  const FrameOptions& options() const { return options_; }
  double prepareMs() const { return prepare_ms_; }  // preparing the technique for the scene

 private:
  const Scene& scene_;
  FrameOptions options_;
  std::unique_ptr<PreparedTechnique> technique_;
  // The scene's triangle records for shading, kept from frame to frame (shadeFrameInto).
  std::unique_ptr<ShadingTriangleTable> shading_triangles_;
  // The objects' hierarchy and the last frame's visible objects, when culling is on.
  std::unique_ptr<OcclusionCuller> occlusion_;
  double prepare_ms_ = 0;
};

// One frame, the technique prepared for it: its preparation is timed as the pass "prepare".
FrameResult renderFrame(const Scene& scene, const FrameOptions& options);

}  // namespace penumbra
