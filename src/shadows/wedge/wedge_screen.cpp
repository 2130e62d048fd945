#include "shadows/wedge/wedge_screen.h"

#include <algorithm>

namespace penumbra {

ScreenProjection screenProjection(const View& view) {
  ScreenProjection p;
  p.view_projection = dmat4(view.view_projection);
  p.plane_to_clip = glm::transpose(glm::inverse(p.view_projection));
  p.width = view.width;
  p.height = view.height;
  return p;
}

ScreenPlane toScreenPlane(const Plane& world, const ScreenProjection& projection) {
  // World plane value = (n, d) . X = (n, d) . M^-1 clip = q . clip with q = M^-T (n, d), and
  // clip = w (ndc_x, ndc_y, z, 1) for a finite point (core/view.h). Dividing by w and writing
  // ndc in pixels: ndc_x = 2 sx / W - 1, ndc_y = 1 - 2 sy / H.
  const dvec4 q = projection.plane_to_clip * dvec4(world.n, world.d);
  ScreenPlane p;
  p.a = float(2.0 * q.x / projection.width);
  p.b = float(-2.0 * q.y / projection.height);
  p.c = float(q.z);
  p.d = float(q.w - q.x + q.y);
  return p;
}

namespace {

// Depth of a homogeneous world point (w = 1 point, w = 0 direction); returns false when the
// point is behind the near plane (then the wedge may cover depths up to 1).
bool depthOf(const ScreenProjection& projection, const dvec4& p, float& depth) {
  const dvec4 clip = projection.view_projection * p;
  if (!(clip.w - clip.z > 0.0)) return false;
  depth = float(clip.z / clip.w);
  return true;
}

}  // namespace

ScreenWedge toScreenWedge(const Wedge& wedge, const std::vector<dvec4>& corners,
                          const ScreenProjection& projection, bool smooth) {
  ScreenWedge s;
  s.front = toScreenPlane(wedge.front, projection);
  s.back = toScreenPlane(wedge.back, projection);
  s.left = toScreenPlane(wedge.left, projection);
  s.right = toScreenPlane(wedge.right, projection);
  const WedgeIntensityConstants k = wedgeIntensityConstants(wedge);
  s.k = {float(k.front_left), float(k.back_left), float(k.front_right), float(k.back_right),
         float(k.left), float(k.right)};
  s.smooth = smooth;
  float z_near = 0.0f, z_far = 1.0f;
  bool all_in_front = !corners.empty();
  for (const dvec4& p : corners) {
    float z;
    if (!depthOf(projection, p, z)) {
      all_in_front = false;
      break;
    }
    z_near = std::max(z_near, z);
    z_far = std::min(z_far, z);
  }
  // The float depth buffer and the plane evaluation round: widen the range by a few ulps.
  s.z_near = all_in_front ? z_near * (1.0f + 1e-5f) : 2.0f;
  s.z_far = all_in_front ? z_far * (1.0f - 1e-5f) : 0.0f;
  return s;
}

}  // namespace penumbra
