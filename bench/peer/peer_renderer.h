#pragma once
// The llvmpipe peer's frame: Everitt & Kilgard's z-fail stencil shadow volumes in OpenGL 4.5,
// the classic multipass form:
//   1. eye pass: depth and ambient of every triangle (one static vertex and index buffer);
//   2. per light: silhouette on the CPU (findSilhouette, as our renderer does every frame),
//      volume indices streamed to the GPU, volumes extruded to infinity in the vertex shader,
//      two-sided stencil z-fail with INCR_WRAP / DECR_WRAP, depth and colour writes off;
//   3. per light: Lambert + Blinn-Phong added where the stencil is 0, depth test GL_EQUAL.
// A current OpenGL 4.5 context (HeadlessGl) is required for the object's whole life.
//
// Depth uses our conventions (core/view.h): View::view_projection as is, reversed-Z with an
// infinite far plane, glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), depth cleared to 0 and
// tested GL_GREATER. Volume vertices at infinity (w = 0) land on depth 0 and are never clipped.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/view.h"
#include "peer_volumes.h"
#include "scene/scene.h"

namespace penumbra {

enum class DepthFormat { kDepth24Stencil8, kDepth32FStencil8 };

struct PeerOptions {
  int width = 640;
  int height = 427;
  CasterMode casters = CasterMode::kOneSided;
  DepthFormat depth = DepthFormat::kDepth24Stencil8;
  // glFinish after the eye pass and after each light's stencil pass, to time the passes apart.
  // Off for the headline numbers: the extra flushes cost llvmpipe a re-bin of the scene.
  bool pass_breakdown = false;
};

struct PeerFrameStats {
  double eye_ms = 0.0;      // with pass_breakdown only
  double volumes_ms = 0.0;  // silhouette, index upload and stencil pass (with pass_breakdown)
  double shading_ms = 0.0;  // lit passes (with pass_breakdown)
  uint64_t silhouette_edges = 0;
  uint64_t side_quads = 0;
  uint64_t cap_triangles = 0;
  uint64_t volume_triangles = 0;
};

class PeerRenderer {
 public:
  PeerRenderer(const Scene& scene, const PeerOptions& options);
  ~PeerRenderer();
  PeerRenderer(const PeerRenderer&) = delete;
  PeerRenderer& operator=(const PeerRenderer&) = delete;

  // Renders one complete frame, glFinish included.
  PeerFrameStats renderFrame();
  // The colour buffer, linear RGB (row 0 at the top, as Image wants).
  Image<vec3> readColor() const;

  size_t sceneTriangles() const { return scene_triangles_; }
  size_t sceneVertices() const { return scene_vertices_; }  // after merging equal corners

 private:
  struct Gl;
  const Scene& scene_;
  PeerOptions options_;
  View view_;
  std::vector<VolumeMesh> volume_meshes_;
  uint32_t volume_far_offset_ = 0;
  VolumeIndices volume_indices_;
  size_t scene_triangles_ = 0;
  size_t scene_vertices_ = 0;
  uint32_t closed_index_count_ = 0;  // closed meshes come first in the index buffer: culled
  uint32_t open_index_count_ = 0;    // then open ones, drawn two-sided as the eye pass does
  std::unique_ptr<Gl> gl_;
};

}  // namespace penumbra
