#pragma once
// The eye's projection and the numeric conventions every pass shares.
//
// Depth convention (README, Conventions): reversed-Z with an infinite far plane.
// The projection maps a view-space point at distance w = -z_view in front of the eye to
//   clip = (x_clip, y_clip, near * w_h, w)      (w_h is the point's homogeneous w: 1 or 0)
//   depth = clip.z / clip.w = near / w          (1 at the near plane, 0 at infinity)
// so points extruded to infinity (w_h = 0) land exactly on depth 0 and are never clipped by a
// far plane (Everitt & Kilgard's infinite shadow volumes). Depth is affine in screen space, so
// every primitive's depth is one plane equation d(x, y) = a x + b y + c.
// Near-plane clipping keeps clip.w - clip.z >= 0.
//
// Screen space: pixel (x, y) covers [x, x+1) x [y, y+1), its centre is (x + 0.5, y + 0.5),
// y grows downwards (row 0 is the top of the image).
#include <penumbra/core/math.h>

namespace penumbra {

struct View {
  int width = 0;
  int height = 0;
  float near_plane = 0.05f;  // world units
  vec3 eye{0.0f};
  mat4 view{1.0f};       // world -> view
  mat4 projection{1.0f}; // view -> clip, reversed-Z infinite (above)
  mat4 view_projection{1.0f};
  mat4 inverse_view{1.0f};

  // Builds a view looking from `eye` at `target`; fov_y in degrees. Throws on a degenerate
  // camera (eye == target, up parallel to the view direction, non-positive near or size).
  static View lookAt(int width, int height, vec3 eye, vec3 target, vec3 up, float fov_y_degrees,
                     float near_plane);

  // Clip-space position of a homogeneous world point (w = 1 for points, 0 for directions).
  vec4 toClip(const vec4& world) const { return view_projection * world; }

  // World position of the visible point at pixel (x, y) whose stored depth is `depth` (> 0).
  // This is how every technique and the oracle find the shaded points from the depth buffer.
  dvec3 unproject(int x, int y, float depth) const;
  // Same for an arbitrary screen position (sx, sy) in pixels.
  dvec3 unprojectScreen(double sx, double sy, double depth) const;
};

}  // namespace penumbra
