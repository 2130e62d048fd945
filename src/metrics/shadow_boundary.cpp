#include "metrics/shadow_boundary.h"

#include <cmath>

namespace penumbra {

BoundaryAgreement compareHardShadows(const Image<float>& technique, const Image<float>& oracle,
                                     const Image<float>& depth) {
  PENUMBRA_CHECK(technique.width() == oracle.width() && technique.height() == oracle.height() &&
                     depth.width() == oracle.width() && depth.height() == oracle.height(),
                 "images differ in size: {}x{}, {}x{} and depth {}x{}", technique.width(),
                 technique.height(), oracle.width(), oracle.height(), depth.width(),
                 depth.height());
  const int w = oracle.width(), h = oracle.height();
  BoundaryAgreement r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float d = depth.at(x, y);
      if (!(d > 0.0f)) continue;
      ++r.covered;
      const bool lit_oracle = oracle.at(x, y) > 0.5f;
      const bool lit_technique = technique.at(x, y) > 0.5f;
      if (lit_technique == lit_oracle) continue;
      ++r.differing;
      bool tie = false;
      for (int dy = -1; dy <= 1 && !tie; ++dy)
        for (int dx = -1; dx <= 1 && !tie; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const float nd = depth.at(nx, ny);
          tie = (oracle.at(nx, ny) > 0.5f) != lit_oracle ||
                (technique.at(nx, ny) > 0.5f) != lit_technique || !(nd > 0.0f) ||
                std::fabs(nd - d) > 0.02f * d;
        }
      r.off_boundary += !tie;
    }
  return r;
}

}  // namespace penumbra
