#include "shadows/wedge/wedge2002_kernel.h"

#include <cmath>

#include "shadows/wedge/wedge_frame.h"

namespace penumbra {
namespace {

// Screen-space plane values along the pixel's view ray are affine in the depth z:
// E(z) = e0 + c z, and moving away from the eye decreases z (reversed-Z).
struct RayPlane {
  float e0, c;
};

float intensityAt(const ScreenWedge& w, float sx, float sy, float z) {
  float s = screenIntensity(w.k, w.front.eval(sx, sy, z), w.back.eval(sx, sy, z),
                            w.left.eval(sx, sy, z), w.right.eval(sx, sy, z));
  return w.smooth ? smoothFalloff(s) : s;
}

}  // namespace

void wedge2002Kernel(const TileEdges& e, const ScreenWedge& w, int face, float li_scale,
                     const WedgeKernelTarget& target, WedgeKernelCounts& counts) {
  const ScreenPlane* planes[5] = {&w.front, &w.back, &w.left, &w.right, &w.bottom};
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
      if (!(stored > 0.0f)) continue;
      const float z_entry = row_depth + e.da * float(rx);
      if (!(z_entry > stored)) continue;  // the surface hides the entry: the depth test fails
      const float sx = float(x) + 0.5f;
      // Entry intensity: 1 on the front plane, 0 on the back and side planes (section 5).
      float s_f = face == kFront ? 1.0f : 0.0f;
      if (face == kFar) s_f = intensityAt(w, sx, sy, z_entry);
      // Exit: the first plane whose inside ends as z decreases from the entry.
      float z_exit = 0.0f;  // infinity
      int exit_plane = kFar;
      for (int p = 0; p < 5; ++p) {
        const RayPlane rp{(planes[p]->a * sx + planes[p]->b * sy) + planes[p]->d, planes[p]->c};
        if (!(rp.c > 0.0f) || p == face) continue;
        const float z = -rp.e0 / rp.c;
        if (z < z_entry && z > z_exit) {
          z_exit = z;
          exit_plane = p;
        }
      }
      float s_i;
      if (stored >= z_exit) {  // the depth-buffer point is inside the wedge
        s_i = intensityAt(w, sx, sy, stored);
        ++counts.inside;
      } else if (exit_plane == kFront) {
        s_i = 1.0f;
      } else if (exit_plane == kFar) {
        s_i = intensityAt(w, sx, sy, z_exit);
      } else {
        s_i = 0.0f;  // back plane, or a side plane cancelled by the neighbour (section 5)
      }
      li_row[x] = liAdd(li_row[x], int32_t(std::nearbyint(li_scale * (s_i - s_f))));
      ++counts.writes;
    }
  }
}

}  // namespace penumbra
