#pragma once
// Error between two images of the same size: visibility buffers against the oracle's, or two
// renders (the metrics module uses core only).
//
// Per-pixel error: |a - b| for gray images; for RGB the largest channel difference, so a pixel
// is "off" when any channel is. Non-finite values (a NaN visibility is a bug somewhere) are not
// averaged: they are counted in `count_nonfinite` and as over the tolerance, and make max_error
// infinite.
#include <cstddef>
#include <cstdint>

#include <penumbra/core/image.h>
#include <penumbra/core/math.h>

namespace penumbra {

struct ImageDifference {
  size_t pixels = 0;                // pixels compared (inside the mask)
  double mae = 0;                   // mean absolute error over the finite pixels
  double rmse = 0;                  // root mean squared error over the finite pixels
  double max_error = 0;
  size_t count_over_tolerance = 0;  // error > tolerance (strictly), non-finite included
  double fraction_over_tolerance = 0;  // count_over_tolerance / pixels
  size_t count_nonfinite = 0;
};

// `mask`, when given, has the images' size; only pixels where it is non-zero are compared.
// Throws penumbra::Error when the sizes differ or the tolerance is negative or not a number.
ImageDifference compareImages(const Image<float>& a, const Image<float>& b, double tolerance,
                              const Image<uint8_t>* mask = nullptr);
ImageDifference compareImages(const Image<vec3>& a, const Image<vec3>& b, double tolerance,
                              const Image<uint8_t>* mask = nullptr);

// Exact differences, for buffers that must agree to the last bit (culling on and off, repeated
// runs): how many pixels differ at all and by how much at most. A pixel differs when its two
// values compare unequal (+0 and -0 are equal; a NaN differs from everything, itself included).
// The largest difference is |a - b| computed in double; infinite when a differing pixel has a
// non-finite difference.
struct ExactDifference {
  size_t pixels = 0;     // pixels compared
  size_t differing = 0;  // a[i] != b[i]
  double max_error = 0;  // 0 when none differs
};

// Throws penumbra::Error when the sizes differ.
ExactDifference compareExact(const Image<float>& a, const Image<float>& b);

}  // namespace penumbra
