#pragma once
#include <cmath>

namespace penumbra {

// A number in [0, 4) that increases with the angle of (x, y) from the x axis as atan2(y, x)
// does (the same order), at a fraction of its cost: for sorting by angle (atan2 was a large
// part of the wedge hulls' time, bench/README.md).
inline double pseudoAngle(double x, double y) {
  const double sum = std::fabs(x) + std::fabs(y);
  if (!(sum > 0.0)) return 0.0;
  const double p = y / sum;  // in [-1, 1]
  return x >= 0.0 ? (p >= 0.0 ? p : 4.0 + p) : 2.0 - p;
}

}  // namespace penumbra
