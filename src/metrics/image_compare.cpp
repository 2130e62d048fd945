#include "metrics/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace penumbra {
namespace {

template <typename T>
void checkComparable(const Image<T>& a, const Image<T>& b, double tolerance,
                     const Image<uint8_t>* mask) {
  PENUMBRA_CHECK(a.width() == b.width() && a.height() == b.height(),
                 "cannot compare images of different sizes: {}x{} and {}x{}", a.width(),
                 a.height(), b.width(), b.height());
  PENUMBRA_CHECK(tolerance >= 0.0, "comparison tolerance {} must be a number >= 0", tolerance);
  if (mask) {
    PENUMBRA_CHECK(mask->width() == a.width() && mask->height() == a.height(),
                   "comparison mask is {}x{} but the images are {}x{}", mask->width(),
                   mask->height(), a.width(), a.height());
  }
}

// Accumulates in double, in pixel order, so results do not depend on anything but the inputs.
template <typename T, typename ErrorFn>
ImageDifference accumulate(const Image<T>& a, const Image<T>& b, double tolerance,
                           const Image<uint8_t>* mask, ErrorFn error_of) {
  checkComparable(a, b, tolerance, mask);
  ImageDifference d;
  double sum = 0;
  double sum_squared = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (mask && (*mask)[i] == 0) continue;
    ++d.pixels;
    const double e = error_of(a[i], b[i]);
    if (!std::isfinite(e)) {
      ++d.count_nonfinite;
      ++d.count_over_tolerance;
      d.max_error = std::numeric_limits<double>::infinity();
      continue;
    }
    sum += e;
    sum_squared += e * e;
    if (e > d.max_error) d.max_error = e;
    if (e > tolerance) ++d.count_over_tolerance;
  }
  const size_t finite = d.pixels - d.count_nonfinite;
  if (finite > 0) {
    d.mae = sum / double(finite);
    d.rmse = std::sqrt(sum_squared / double(finite));
  }
  if (d.pixels > 0) d.fraction_over_tolerance = double(d.count_over_tolerance) / double(d.pixels);
  return d;
}

}  // namespace

ImageDifference compareImages(const Image<float>& a, const Image<float>& b, double tolerance,
                              const Image<uint8_t>* mask) {
  return accumulate(a, b, tolerance, mask,
                    [](float x, float y) { return std::abs(double(x) - double(y)); });
}

ImageDifference compareImages(const Image<vec3>& a, const Image<vec3>& b, double tolerance,
                              const Image<uint8_t>* mask) {
  return accumulate(a, b, tolerance, mask, [](const vec3& x, const vec3& y) {
    double e = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(double(x[c]) - double(y[c]));
      if (!std::isfinite(d)) return d;
      if (d > e) e = d;
    }
    return e;
  });
}

ExactDifference compareExact(const Image<float>& a, const Image<float>& b) {
  PENUMBRA_CHECK(a.width() == b.width() && a.height() == b.height(),
                 "cannot compare images of different sizes: {}x{} and {}x{}", a.width(),
                 a.height(), b.width(), b.height());
  ExactDifference d;
  d.pixels = a.size();
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    ++d.differing;
    const double e = std::abs(double(a[i]) - double(b[i]));
    d.max_error = std::isfinite(e) ? std::max(d.max_error, e)
                                   : std::numeric_limits<double>::infinity();
  }
  return d;
}

}  // namespace penumbra
