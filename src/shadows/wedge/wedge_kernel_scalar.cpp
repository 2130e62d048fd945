#include <cmath>

#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {

void wedgeKernelScalar(const TileEdges& e, const WedgeKernelWork& work,
                       const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
  const ScreenWedge* w = work.wedge;
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    const size_t i = target.index(x, y);
    const float stored = target.depth[i];
    if (!(stored > 0.0f)) return;  // background: nothing to shadow
    int32_t value = 0;
    bool write = false;
    if (work.umbra_value != 0) {
      const float d = triangleDepthAt(e, x, y);
      if (work.rule == DepthRule::Closer ? d > stored : d <= stored) {
        value += work.umbra_value;
        write = true;
      }
    }
    if (w != nullptr) {
      const float sx = float(x) + 0.5f, sy = float(y) + 0.5f;
      const float f = w->front.eval(sx, sy, stored), b = w->back.eval(sx, sy, stored);
      const float l = w->left.eval(sx, sy, stored), r = w->right.eval(sx, sy, stored);
      if (f >= 0.0f && b >= 0.0f && l >= 0.0f && r >= 0.0f) {
        float s = screenIntensity(w->k, f, b, l, r);
        if (w->smooth) s = smoothFalloff(s);
        value += int32_t(std::nearbyint(s * work.li_scale));
        write = true;
        ++counts.inside;
      }
    }
    if (write) {
      target.li[i] = liAdd(target.li[i], value);
      ++counts.writes;
    }
  });
}

}  // namespace penumbra
