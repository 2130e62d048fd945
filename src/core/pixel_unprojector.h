#pragma once
// View::unproject for passes that unproject many pixels of one view: the point at pixel
// (x, y) with stored depth d lies at the eye plus w = near / d times the pixel's ray, and the
// ray is affine in the pixel centre (view.h's conventions):
//   ndc_x = 2 sx / width - 1,  ndc_y = 1 - 2 sy / height,
//   p = inv_view * (ndc_x w / P00, ndc_y w / P11, -w, 1)
//     = inv_view[3] + w (inv_view[0] ndc_x / P00 + inv_view[1] ndc_y / P11 - inv_view[2]).
// One division per pixel where View::unproject has five and converts the matrix each call;
// the same point up to rounding (tests/test_view.cpp), so it is for techniques that only
// need the point (coverage), not for those that must agree with the oracle bit for bit.
#include <penumbra/core/view.h>

namespace penumbra {

class PixelUnprojector {
 public:
  explicit PixelUnprojector(const View& view) {
    const dmat4 inverse(view.inverse_view);
    const double p00 = double(view.projection[0][0]), p11 = double(view.projection[1][1]);
    near_ = double(view.near_plane);
    origin_ = dvec3(inverse[3]);
    per_x_ = dvec3(inverse[0]) * (2.0 / (double(view.width) * p00));
    per_y_ = dvec3(inverse[1]) * (-2.0 / (double(view.height) * p11));
    base_ = dvec3(inverse[1]) / p11 - dvec3(inverse[0]) / p00 - dvec3(inverse[2]);
  }

  // The visible point at pixel (x, y)'s centre whose stored depth is `depth` (> 0).
  dvec3 operator()(int x, int y, float depth) const {
    const double w = near_ / double(depth);
    return origin_ + w * (base_ + (double(x) + 0.5) * per_x_ + (double(y) + 0.5) * per_y_);
  }

 private:
  double near_ = 0.0;
  dvec3 origin_{0.0}, per_x_{0.0}, per_y_{0.0}, base_{0.0};
};

}  // namespace penumbra
