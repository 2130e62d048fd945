#include "metrics/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace penumbra {
namespace {

// Samples of matplotlib's 'inferno' at t = 0, 1/8, ..., 1 (sRGB bytes), except the first,
// moved from (0, 0, 4) to pure black.
constexpr std::array<std::array<uint8_t, 3>, 9> kInferno = {{
    {0, 0, 0},
    {33, 12, 74},
    {87, 16, 110},
    {138, 34, 106},
    {188, 55, 84},
    {228, 90, 49},
    {249, 142, 9},
    {249, 203, 53},
    {252, 255, 164},
}};

uint8_t byteOf(float v) { return uint8_t(std::clamp(std::floor(v + 0.5f), 0.0f, 255.0f)); }

template <typename T, typename ErrorFn>
Image<glm::u8vec3> heatmap(const Image<T>& a, const Image<T>& b, float scale, ErrorFn error_of) {
  PENUMBRA_CHECK(a.width() == b.width() && a.height() == b.height(),
                 "cannot diff images of different sizes: {}x{} and {}x{}", a.width(), a.height(),
                 b.width(), b.height());
  PENUMBRA_CHECK(scale > 0.0f && std::isfinite(scale),
                 "heat map scale {} must be a finite number > 0", scale);
  Image<glm::u8vec3> out(a.width(), a.height());
  for (size_t i = 0; i < a.size(); ++i) {
    const float e = error_of(a[i], b[i]);
    out[i] = std::isfinite(e) ? errorColor(e / scale) : errorColor(1.0f);
  }
  return out;
}

}  // namespace

glm::u8vec3 errorColor(float t) {
  if (std::isnan(t)) t = 1.0f;
  t = std::clamp(t, 0.0f, 1.0f);
  constexpr int kSegments = int(kInferno.size()) - 1;
  const float x = t * float(kSegments);
  const int i = std::min(int(x), kSegments - 1);
  const float f = x - float(i);
  glm::u8vec3 c;
  for (int k = 0; k < 3; ++k) {
    const float lo = kInferno[size_t(i)][size_t(k)];
    const float hi = kInferno[size_t(i) + 1][size_t(k)];
    c[k] = byteOf(lo + (hi - lo) * f);
  }
  return c;
}

Image<glm::u8vec3> diffHeatmap(const Image<float>& a, const Image<float>& b,
                               float max_error_for_scale) {
  return heatmap(a, b, max_error_for_scale, [](float x, float y) { return std::abs(x - y); });
}

Image<glm::u8vec3> diffHeatmap(const Image<vec3>& a, const Image<vec3>& b,
                               float max_error_for_scale) {
  return heatmap(a, b, max_error_for_scale, [](const vec3& x, const vec3& y) {
    const vec3 d = glm::abs(x - y);
    if (!isFinite(d)) return std::numeric_limits<float>::infinity();
    return std::max(d.x, std::max(d.y, d.z));
  });
}

Image<glm::u8vec3> visibilityToImage(const Image<float>& visibility) {
  Image<glm::u8vec3> out(visibility.width(), visibility.height());
  for (size_t i = 0; i < visibility.size(); ++i) {
    const float v = visibility[i];
    const uint8_t g = v > 0.0f ? byteOf(std::min(v, 1.0f) * 255.0f) : 0;  // NaN -> 0
    out[i] = glm::u8vec3(g);
  }
  return out;
}

}  // namespace penumbra
