#pragma once
// Wedges in screen space: the restructured algorithm tests "is the depth-buffer point inside
// the wedge" with screen-space plane equations set up once per wedge (2004 paper, section 3),
// and culls tiles against the same planes (section 4).
#include <cstdint>
#include <vector>

#include "core/view.h"
#include "shadows/wedge/wedge.h"

namespace penumbra {

// E(sx, sy, z) = ((a sx + b sy) + c z) + d for a pixel at (sx, sy) (pixels, centres at +0.5)
// whose reversed-Z depth is z (core/view.h). For a point in front of the eye, E equals the
// world-space plane value n.p + d divided by the point's view distance w > 0: same sign, and
// the same positive factor for every plane at that pixel, so equation (3)'s ratios can use E
// directly (wedge.h, intensityFromPlaneValues). Evaluated in float, in exactly this order, by
// the kernels and their scalar twins.
struct ScreenPlane {
  float a = 0, b = 0, c = 0, d = 1;  // default: always inside (E = 1)
  float eval(float sx, float sy, float z) const { return ((a * sx + b * sy) + c * z) + d; }
};

// The view's transforms in double, set up once per frame: world planes to screen planes (the
// inverse transpose of view_projection) and world points to clip space.
struct ScreenProjection {
  dmat4 view_projection;
  dmat4 plane_to_clip;  // transpose(inverse(view_projection))
  int width = 0, height = 0;
};
ScreenProjection screenProjection(const View& view);

ScreenPlane toScreenPlane(const Plane& world, const ScreenProjection& projection);

// Float copies of WedgeIntensityConstants for the pixel kernels: s = b (r L Fl Dr + l R Fr Dl)
// / ((r L + l R) Dl Dr), Dl = f Bl + b Fl, Dr = f Br + b Fr (wedge.h).
struct ScreenIntensity {
  float front_left, back_left, front_right, back_right, left, right;
};

// The wedge is the region inside its four planes (light_wedges.cpp); the Figure 6 bottom plane of
// the wedge builder is not used.
struct ScreenWedge {
  ScreenPlane front, back, left, right;
  ScreenIntensity k;
  bool smooth = false;      // Falloff::Smooth
  // The front face is exactly the unit edge's umbra quad (its front rays do not cross), so the
  // frame draws that quad once for both (single-pass, section 6.2; the 2002 entry values).
  bool front_quad = false;
  // Reversed-Z depth range the wedge can occupy on screen: z_near >= depth of every wedge
  // point in front of the eye, z_far <= it (0 when the wedge reaches infinity). For the
  // z-range quick reject of section 4.
  float z_near = 1.0f, z_far = 0.0f;
};

// `corners`: the wedge polyhedron's vertices, homogeneous (w = 0: directions to infinity); the
// depth range is theirs, since depth over a convex polyhedron in front of the eye is extreme at
// its vertices (depth is a ratio of affine functions).
ScreenWedge toScreenWedge(const Wedge& wedge, const std::vector<dvec4>& corners,
                          const ScreenProjection& projection, bool smooth);

// Light intensity in [0, 1] from the four plane values of a point inside the wedge; the float
// formula the kernels evaluate (same operations, same order as the SIMD twin).
inline float screenIntensity(const ScreenIntensity& k, float f, float b, float l, float r) {
  const float dl = f * k.back_left + b * k.front_left;
  const float dr = f * k.back_right + b * k.front_right;
  const float rl = r * k.left;
  const float lr = l * k.right;
  const float numerator = b * ((rl * k.front_left) * dr + (lr * k.front_right) * dl);
  const float denominator = ((rl + lr) * dl) * dr;
  // A zero denominator only happens on the silhouette edge itself or where the side planes
  // meet: measure-zero sets where half the light is the symmetric answer.
  const float s = denominator > 0.0f ? numerator / denominator : 0.5f;
  return s < 0.0f ? 0.0f : (s > 1.0f ? 1.0f : s);
}

inline float smoothFalloff(float s) { return (3.0f * s) * s - ((2.0f * s) * s) * s; }

}  // namespace penumbra
