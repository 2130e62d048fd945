#include "evaluation/fidelity_strip.h"

#include <algorithm>

#include "core/error.h"
#include "core/image_io.h"
#include "metrics/heatmap.h"

namespace penumbra {

Image<glm::u8vec3> shrinkImage(const Image<glm::u8vec3>& image, int factor) {
  PENUMBRA_CHECK(factor >= 1, "shrink factor {} is below 1", factor);
  if (factor == 1) return image;
  const int w = (image.width() + factor - 1) / factor, h = (image.height() + factor - 1) / factor;
  Image<glm::u8vec3> out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::uvec3 sum(0);
      unsigned n = 0;
      for (int sy = y * factor; sy < std::min((y + 1) * factor, image.height()); ++sy)
        for (int sx = x * factor; sx < std::min((x + 1) * factor, image.width()); ++sx) {
          sum += glm::uvec3(image.at(sx, sy));
          ++n;
        }
      out.at(x, y) = glm::u8vec3((sum + glm::uvec3(n / 2)) / n);  // rounded mean
    }
  return out;
}

Image<glm::u8vec3> fidelityStrip(const Image<float>& technique, const Image<float>& oracle,
                                 float heat_scale, int shrink) {
  const Image<glm::u8vec3> heat = diffHeatmap(technique, oracle, heat_scale);  // checks sizes
  const Image<glm::u8vec3> panels[3] = {shrinkImage(visibilityToImage(technique), shrink),
                                        shrinkImage(visibilityToImage(oracle), shrink),
                                        shrinkImage(heat, shrink)};
  constexpr int kGap = 2;
  const int w = panels[0].width(), h = panels[0].height();
  Image<glm::u8vec3> strip(3 * w + 2 * kGap, h, glm::u8vec3(255));
  for (int p = 0; p < 3; ++p)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) strip.at(p * (w + kGap) + x, y) = panels[p].at(x, y);
  return strip;
}

void writeFidelityStrip(const std::string& path, const Image<float>& technique,
                        const Image<float>& oracle, float heat_scale, int shrink) {
  writePngRgb8(path, fidelityStrip(technique, oracle, heat_scale, shrink));
}

}  // namespace penumbra
