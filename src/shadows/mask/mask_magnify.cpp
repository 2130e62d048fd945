#include "shadows/mask/mask_magnify.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace penumbra {

Image<float> magnifyBilinear(const Image<float>& low, int width, int height) {
  Image<float> out;
  out.resizeForOverwrite(width, height);
  const int lw = low.width(), lh = low.height();
  const double sx = double(lw) / double(width), sy = double(lh) / double(height);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    const double v = std::clamp((y + 0.5) * sy - 0.5, 0.0, double(lh - 1));
    const int y0 = int(v), y1 = std::min(y0 + 1, lh - 1);
    const float fy = float(v - y0);
    const float* r0 = low.row(y0);
    const float* r1 = low.row(y1);
    float* o = out.row(y);
    for (int x = 0; x < width; ++x) {
      const double u = std::clamp((x + 0.5) * sx - 0.5, 0.0, double(lw - 1));
      const int x0 = int(u), x1 = std::min(x0 + 1, lw - 1);
      const float fx = float(u - x0);
      const float top = r0[x0] + (r0[x1] - r0[x0]) * fx;
      const float bottom = r1[x0] + (r1[x1] - r1[x0]) * fx;
      o[x] = top + (bottom - top) * fy;
    }
  });
  return out;
}

}  // namespace penumbra
