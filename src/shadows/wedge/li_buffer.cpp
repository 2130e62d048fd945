#include "shadows/wedge/li_buffer.h"

#include <algorithm>

#include "core/parallel.h"

namespace penumbra {

Image<float> liToVisibility(const LiBuffer& li, const Image<float>& depth, int full, bool hard) {
  Image<float> v(li.width(), li.height(), 1.0f);
  parallelFor(size_t(li.height()), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < li.width(); ++x) {
      if (!(depth.at(x, y) > 0.0f)) continue;
      if (hard) {
        v.at(x, y) = li.at(x, y) == full ? 1.0f : 0.0f;
      } else {
        v.at(x, y) = float(std::clamp<int>(li.at(x, y), 0, full)) / float(full);
      }
    }
  });
  return v;
}

}  // namespace penumbra
