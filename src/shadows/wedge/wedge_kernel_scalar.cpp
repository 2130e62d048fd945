#include <cmath>

#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {

void wedgeKernelScalar(const TileEdges& e, const WedgeKernelWork& work,
                       const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
  const ScreenWedge* w = work.wedge;
  // Covered: inside all three edges (>= 0).
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    const size_t i = target.index(x, y);
    const float stored = target.depth[i];
    if (!(stored > 0.0f)) return;  // background: nothing to shadow
    int32_t value = 0;
    bool write = false;
    // Umbra part: add umbra_value where the triangle's depth passes `rule`.
    if (work.umbra_value != 0) {
      const float d = triangleDepthAt(e, x, y);
      if (work.rule == DepthRule::Closer ? d > stored : d <= stored) {
        value += work.umbra_value;
        write = true;
      }
    }
    // Penumbra part: is the depth-buffer point inside all four wedge planes?
    if (w != nullptr) {
      const float sx = float(x) + 0.5f, sy = float(y) + 0.5f;
      const float f = w->front.eval(sx, sy, stored), b = w->back.eval(sx, sy, stored);
      const float l = w->left.eval(sx, sy, stored), r = w->right.eval(sx, sy, stored);
      if (f >= 0.0f && b >= 0.0f && l >= 0.0f && r >= 0.0f) {
        // screenIntensity (wedge_screen.h), operation for operation.
        float s = screenIntensity(w->k, f, b, l, r);
        // smoothFalloff: (3 s) s - ((2 s) s) s
        if (w->smooth) s = smoothFalloff(s);
        // round(li_scale s): to nearest, ties to even.
        value += int32_t(std::nearbyint(s * work.li_scale));
        write = true;
        ++counts.inside;
      }
    }
    // Add to the 16-bit LI buffer (liAdd, wrapping), pixel by pixel.
    if (write) {
      target.li[i] = liAdd(target.li[i], value);
      ++counts.writes;
    }
  });
}

}  // namespace penumbra
