#include "shadows/wedge/wedge2002_kernel.h"

#include <cmath>

#include "shadows/wedge/light_wedges.h"

namespace penumbra {

void wedge2002Kernel(const TileEdges& e, const ScreenWedge& w, int face, float li_scale,
                     const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    const size_t i = target.index(x, y);
    const float stored = target.depth[i];
    if (!(stored > 0.0f)) return;
    const float sx = float(x) + 0.5f, sy = float(y) + 0.5f;
    // p_i is p itself exactly when p lies between the entry p_f and the exit p_b, that is on
    // the inner side of every wedge plane. Deciding it from the plane values at p rather than
    // from the depths of the intersection points makes the decision exact at shared side
    // planes: the neighbour evaluates the same plane negated, so a point is inside exactly
    // one of the two (comparing rounded intersection depths instead dropped or doubled the
    // neighbour's contribution at points within a rounding error of the plane).
    const float f = w.front.eval(sx, sy, stored), b = w.back.eval(sx, sy, stored);
    const float l = w.left.eval(sx, sy, stored), r = w.right.eval(sx, sy, stored);
    const bool inside = f >= 0.0f && b >= 0.0f && l >= 0.0f && r >= 0.0f;
    // Entry intensity: 1 on the front plane, 0 on the back and side planes (section 5), where
    // the rasterized face passes the depth test. Exits through the front plane (s_i = 1) are
    // counted by the back-facing front face's own fragment (wedge_technique.cpp), the same
    // snapped triangles, so a ray's entries and exits pair up exactly; a choice between the
    // front plane and a side plane made from rounded intersection depths instead disagreed
    // with the rasterized faces of the neighbouring wedge near their common edge and left
    // +-255 streaks along it. Where the front rays cross (Figure 6) the front face is not the
    // whole umbra quad, which is then counted as a hard quad instead: the entry counts 0.
    const float z_face = triangleDepthAt(e, x, y);
    const float s_f = face == kFront && w.front_quad && z_face > stored ? 1.0f : 0.0f;
    // Otherwise p_i = p_b, on the back plane or on a side plane (cancelled by the
    // neighbour's entry, section 5): 0.
    float s_i = 0.0f;
    if (inside) {
      s_i = screenIntensity(w.k, f, b, l, r);
      if (w.smooth) s_i = smoothFalloff(s_i);
      ++counts.inside;
    } else if (s_f == 0.0f) {
      return;
    }
    target.li[i] = liAdd(target.li[i], int32_t(std::nearbyint(li_scale * (s_i - s_f))));
    ++counts.writes;
  });
}

}  // namespace penumbra
