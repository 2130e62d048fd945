#include <cmath>

#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {

void wedgeKernelScalar(const TileEdges& e, const WedgeKernelWork& work,
                       const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
  const ScreenWedge* w = work.wedge;
  for (int y = e.y0; y <= e.y1; ++y) {
    const int ry = y - e.ty0;
    const float row_depth = e.dc + e.db * float(ry);
    const float sy = float(y) + 0.5f;
    const int32_t r0 = e.e0[0] + e.dy[0] * ry, r1 = e.e0[1] + e.dy[1] * ry,
                  r2 = e.e0[2] + e.dy[2] * ry;
    const float* depth_row = target.depth + size_t(y) * target.stride;
    int16_t* li_row = target.li + size_t(y) * target.stride;
    for (int x = e.x0; x <= e.x1; ++x) {
      const int rx = x - e.tx0;
      if (!((r0 + e.dx[0] * rx) >= 0 && (r1 + e.dx[1] * rx) >= 0 && (r2 + e.dx[2] * rx) >= 0))
        continue;
      ++counts.covered;
      const float stored = depth_row[x];
      if (!(stored > 0.0f)) continue;  // background: nothing to shadow
      int32_t value = 0;
      bool write = false;
      if (work.umbra_value != 0) {
        const float d = row_depth + e.da * float(rx);
        if (work.rule == DepthRule::Closer ? d > stored : d <= stored) {
          value += work.umbra_value;
          write = true;
        }
      }
      if (w != nullptr) {
        const float sx = float(x) + 0.5f;
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
        li_row[x] = liAdd(li_row[x], value);
        ++counts.writes;
      }
    }
  }
}

}  // namespace penumbra
