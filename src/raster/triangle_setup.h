#pragma once
// Clipping, snapping and edge/depth setup of triangles given in clip space.
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace penumbra {

// Triangles to rasterize: clip-space vertices (core/view.h conventions) and, per triangle, a
// payload the pass interprets (a primitive id for the eye pass, a signed stencil weight for
// shadow volumes) and flags. Vertices 0 .. shared_count - 1 may live in an array the triangles
// only borrow (the eye pass's vertices, which every pass of the frame shares); the triangles'
// own vertices are numbered after them.
struct ClipTriangles {
  const vec4* shared = nullptr;     // borrowed vertices; must outlive the triangles' use
  size_t shared_count = 0;
  std::vector<vec4> clip;           // own clip-space vertices, numbered from shared_count
  std::vector<uint32_t> indices;    // 3 per triangle
  std::vector<int32_t> payload;     // 1 per triangle
  std::vector<uint8_t> flags;       // 1 per triangle, kCullBackFace...; may be empty (= 0)
  // Shadow volumes: 2 per triangle, the visible triangles (eye-pass primitive ids) at whose
  // pixels the stencil never counts it (shadow_stencil.cpp); empty, or kNoOwner, for none.
  std::vector<uint32_t> owners;

  ClipTriangles() = default;
  explicit ClipTriangles(const std::vector<vec4>& borrowed)
      : shared(borrowed.data()), shared_count(borrowed.size()) {}

  size_t size() const { return payload.size(); }
  size_t vertexCount() const { return shared_count + clip.size(); }
  const vec4& vertex(uint32_t i) const {
    return i < shared_count ? shared[i] : clip[i - shared_count];
  }
  uint32_t addVertex(const vec4& v) {
    clip.push_back(v);
    return uint32_t(vertexCount() - 1);
  }
  // Room for n own vertices; returns the number of the first, to be written via ownVertex.
  uint32_t appendVertices(size_t n) {
    const uint32_t first = uint32_t(vertexCount());
    clip.resize(clip.size() + n);
    return first;
  }
  vec4* ownVertex(uint32_t i) { return clip.data() + (i - shared_count); }
  // Element by element: a range insert of an initializer list costs a call and a copy loop
  // per triangle, which shows in the profile of a pass adding tens of thousands of polygons.
  void add(uint32_t i0, uint32_t i1, uint32_t i2, int32_t value, uint8_t flag = 0) {
    indices.push_back(i0);
    indices.push_back(i1);
    indices.push_back(i2);
    payload.push_back(value);
    flags.push_back(flag);
    if (!owners.empty()) {
      owners.push_back(kNoOwner);
      owners.push_back(kNoOwner);
    }
  }
  // As add, with the two owners (either may be kNoOwner).
  void addOwned(uint32_t i0, uint32_t i1, uint32_t i2, int32_t value, uint8_t flag,
                uint32_t owner0, uint32_t owner1) {
    if (owners.empty()) owners.assign(2 * payload.size(), kNoOwner);
    indices.push_back(i0);
    indices.push_back(i1);
    indices.push_back(i2);
    payload.push_back(value);
    flags.push_back(flag);
    owners.push_back(owner0);
    owners.push_back(owner1);
  }
  // Room for `triangles` more triangles (with owners) and `vertices` more own vertices.
  void reserve(size_t triangles, size_t vertices) {
    indices.reserve(indices.size() + 3 * triangles);
    payload.reserve(payload.size() + triangles);
    flags.reserve(flags.size() + triangles);
    owners.reserve(owners.size() + 2 * triangles);
    clip.reserve(clip.size() + vertices);
  }

  static constexpr uint32_t kNoOwner = 0xffffffffu;  // = kNoPrimitive (depth_buffer.h)
};

inline constexpr uint8_t kCullBackFace = 1;  // drop the triangle when the eye sees its back
inline constexpr uint8_t kZFail = 2;         // shadow volumes: count from infinity (z-fail)

// A triangle ready for the pixel kernels, in screen space.
struct SetupTriangle {
  // Edge functions in 28.4 units: pixel (x, y) is inside iff for all i
  //   A[i] * (16x + 8) + B[i] * (16y + 8) + C[i] >= 0.
  // C includes the top-left fill-rule bias, so an edge two triangles share is covered by
  // exactly one of them (a pixel centre on a left or top edge belongs to the triangle).
  int32_t A[3], B[3];
  int64_t C[3];
  // Depth plane over pixel coordinates: depth(sx, sy) = a sx + b sy + c, sx, sy in pixels,
  // reversed-Z (core/view.h). Computed from the unsnapped projected vertices (coverage uses the
  // snapped ones) in the input vertex order, so a triangle drawn twice (eye pass and
  // shadow-volume light cap) gets bit-identical depths.
  double a, b, c;
  float depth_min, depth_max;    // over the vertices
  int32_t min_x, min_y, max_x, max_y;  // covered pixel box, inclusive, clamped to the image
  int32_t payload;               // the input triangle's payload
  int8_t facing;                 // +1 when the eye sees the front (counter-clockwise) side
  uint8_t flags;                 // the input triangle's flags
  uint32_t owners[2] = {ClipTriangles::kNoOwner, ClipTriangles::kNoOwner};  // the input's
};

// A triangle (or a clipped piece of one) on screen that set-up dropped without back-face
// culling: its snapped vertices are collinear, its box holds no pixel centre, or its depth plane
// is singular. It draws nothing, but as a face of a closed shadow volume seen edge-on (the eye
// in its plane) it still separates the volume's inside from its outside on screen, which a
// pass deciding whole tiles by one sample must know (tiled_volume_stencil.cpp).
struct VanishedPiece {
  uint32_t source;  // the input triangle
  // Where it lies on screen, in pixels (pixel x's centre at x + 0.5), snapped: within `slack`
  // of the segment (ax, ay)-(bx, by), between its two vertices farthest apart. The slack is one
  // pixel plus the third vertex's distance from that segment (zero when they are collinear,
  // as for a face seen edge-on): a long sliver is a segment, not its bounding box.
  double ax, ay, bx, by, slack;
  int32_t x0, y0, x1, y1;  // the pixels whose centres lie within `slack` of its vertices' box,
                           // inclusive, clamped to the image (never empty)
  // Depths (reversed-Z, unsnapped) at a and b, affine along the segment between (1 / w is affine
  // along a projected line), and how far the third vertex's depth lies off that: every point
  // of the piece lies within depth_spread of the segment's depth where it projects. Large for
  // a face seen edge-on (its depth runs across the line it projects to).
  double depth_a, depth_b, depth_spread;
};

// Clips each input triangle to the near plane and the guard band, snaps to 28.4 and sets it up:
// edge functions from the snapped vertices, the depth plane from the unsnapped ones.
// Output keeps input order (a clipped triangle's fan pieces stay together), so passes that
// resolve ties by drawing order are deterministic. Zero-area and off-screen triangles vanish.
// `sources`, when given, receives for every output triangle the index of the input triangle it
// came from; `vanished`, when given, every piece on screen that vanished (VanishedPiece), in
// input order.
std::vector<SetupTriangle> setupTriangles(const ClipTriangles& triangles, int width, int height,
                                          std::vector<uint32_t>* sources = nullptr,
                                          std::vector<VanishedPiece>* vanished = nullptr);

}  // namespace penumbra
