#pragma once
// Object-level occlusion culling for the eye pass after dPVS (Aila's thesis, sections 3.1-3.2;
// docs/occlusion-culling.md): a hierarchy over the scene's objects (scene/object_hierarchy.h),
// traversed front to back each frame against an occlusion buffer that batches of visible objects
// are drawn into, the objects visible in the previous frame drawn first, and a cached visible
// point per object queried before its box. Conservative: the eye pass's buffers are bit-identical
// with and without it.
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/object_hierarchy.h"
#include "scene/scene.h"

namespace penumbra {

class OcclusionCuller {
 public:
  // Builds the hierarchy over `scene`, which must outlive the culler and keep its meshes.
  explicit OcclusionCuller(const Scene& scene);

  // Appends to `out` (indices into `clip_vertices`, the frame's clip-space vertices of every mesh,
  // and the global ids as payloads) every triangle that may be visible in `view`, in increasing
  // id order, so the eye pass draws them as it would draw all of them: the same ties. Counts into
  // `stats`. Thread-safe (a lock), but its first occluders are the objects of the frame tracked
  // last, so frames of one view sequence should come one at a time.
  void selectTriangles(const View& view, const std::vector<vec4>& clip_vertices,
                       ClipTriangles& out, Stats& stats, bool simd);
  // Records the objects visible in the eye pass's buffers, and a visible point of each, for the
  // next frame.
  void track(const View& view, const DepthBuffer& depth, const Image<uint32_t>& primitive);

  const ObjectHierarchy& hierarchy() const { return hierarchy_; }

 private:
  std::vector<uint32_t> traverse(const View& view, const std::vector<vec4>& clip_vertices,
                                 Stats& stats, bool simd);
  void drawBatch(const std::vector<uint32_t>& clusters, const std::vector<vec4>& clip_vertices,
                 Stats& stats, bool simd);
  std::vector<uint32_t> retest(const View& view, std::vector<uint32_t> accepted, Stats& stats);
  void emitTriangles(const std::vector<uint32_t>& clusters, ClipTriangles& out);

  ObjectHierarchy hierarchy_;
  std::mutex mutex_;
  // Per cluster: seen in the last frame tracked, and a point of it seen there.
  std::vector<uint8_t> was_visible_;
  std::vector<vec3> visible_point_;
  // Per frame scratch, kept so a frame does not allocate them again.
  DepthBuffer occlusion_;
  std::vector<uint8_t> triangle_marks_;
  std::vector<uint32_t> first_pixel_;
};

}  // namespace penumbra
