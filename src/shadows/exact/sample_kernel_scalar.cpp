#include "shadows/exact/sample_kernel.h"

#include <cmath>

namespace penumbra {

void samplePositionsScalar(const float* radius2, const float* cos_phi, const float* sin_phi,
                           float one_minus_cos_max, float* x, float* y, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const float one_minus_cos = radius2[i] * one_minus_cos_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float tan_theta = std::sqrt(one_minus_cos * (2.0f - one_minus_cos)) / cos_theta;
    x[i] = tan_theta * cos_phi[i];
    y[i] = tan_theta * sin_phi[i];
  }
}

void addEdgeCrossingsScalar(const SampleEdge& e, const float* x, const float* y, int32_t* count,
                            size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const float sa = e.sector_a[0] * x[i] + e.sector_a[1] * y[i];
    const float sb = e.sector_b[0] * x[i] + e.sector_b[1] * y[i];
    const float sl = (e.line[0] * x[i] + e.line[1] * y[i]) + e.line[2];
    const bool crossed = ((sa >= 0.0f) == e.a_side) && ((sb >= 0.0f) == e.b_side) &&
                         ((sl >= 0.0f) != e.centre_side);
    if (crossed) count[i] += e.delta;
  }
}

}  // namespace penumbra
