#include "metrics/shadow_boundary.h"

#include <cmath>

namespace penumbra {

BoundaryAgreement compareHardShadows(const Image<float>& technique, const Image<float>& oracle,
                                     const Image<uint8_t>& mask) {
  PENUMBRA_CHECK(technique.width() == oracle.width() && technique.height() == oracle.height(),
                 "images differ in size: {}x{} vs {}x{}", technique.width(), technique.height(),
                 oracle.width(), oracle.height());
  const int w = oracle.width(), h = oracle.height();
  BoundaryAgreement r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!mask.empty() && !mask.at(x, y)) continue;
      ++r.covered;
      const bool lit_oracle = oracle.at(x, y) > 0.5f;
      if ((technique.at(x, y) > 0.5f) == lit_oracle) continue;
      ++r.differing;
      bool tie = false;
      for (int dy = -1; dy <= 1 && !tie; ++dy)
        for (int dx = -1; dx <= 1 && !tie; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          tie = (oracle.at(nx, ny) > 0.5f) != lit_oracle;
        }
      r.off_boundary += !tie;
    }
  return r;
}

}  // namespace penumbra
