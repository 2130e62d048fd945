#include "shadows/coverage/coverage_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {
CoverageTableData::CoverageTableData(LightOutline outline, int n) : outline_(outline), n_(n) {
  PENUMBRA_CHECK(n >= kMinCoverageTableSize && n <= kMaxCoverageTableSize,
                 "coverage table size {} is outside {}..{}", n, kMinCoverageTableSize,
                 kMaxCoverageTableSize);
  const size_t n1 = size_t(n);
  const double last = double(n - 1);
  if (outline_ == LightOutline::Disk) {
    // (r0, r1, dtheta): the first point on the +x axis, the second at angle dtheta from it. The
    // end nodes dtheta = -pi and pi hold the one-sided limits (sin(+-pi) rounds to +-1e-16, so
    // insideFraction sees the turn's sign), so no cell straddles the jump.
    values_.resize(n1 * n1 * n1);
    parallelFor(n1, [&](size_t i0) {
      const dvec2 q0(double(i0) / last, 0.0);
      float* out = values_.data() + i0 * n1 * n1;
      for (int i1 = 0; i1 < n; ++i1) {
        for (int k = 0; k < n; ++k) {
          const double r1 = double(i1) / last;
          const double dtheta = std::numbers::pi * (2.0 * double(k) / last - 1.0);
          *out++ = float(insideFraction(outline_, q0, r1 * dvec2(std::cos(dtheta), std::sin(dtheta))));
        }
      }
    });
    return;
  }
  values_.resize(n1 * n1 * n1 * n1);
  parallelFor(n1 * n1, [&](size_t first) {
    const dvec2 q0 = squarePoint(int(first / n1), int(first % n1));
    float* out = values_.data() + first * n1 * n1;
    for (int i1 = 0; i1 < n; ++i1) {
      for (int j1 = 0; j1 < n; ++j1) *out++ = float(insideFraction(outline_, q0, squarePoint(i1, j1)));
    }
  });
}

dvec2 CoverageTableData::squarePoint(int i, int j) const {
  const double step = 2.0 / double(n_ - 1);
  return dvec2(double(i) * step - 1.0, double(j) * step - 1.0);
}

float CoverageTableData::lookupInside(const dvec2& lo, const dvec2& hi,
                                      CoverageTable mode) const {
  const double last = double(n_ - 1);
  // Continuous table coordinates, each in [0, n - 1].
  double coords[4];
  int dims;
  if (outline_ == LightOutline::Disk) {
    const double dtheta = std::atan2(lo.x * hi.y - lo.y * hi.x, glm::dot(lo, hi));
    coords[0] = std::min(1.0, glm::length(lo)) * last;
    coords[1] = std::min(1.0, glm::length(hi)) * last;
    coords[2] = std::clamp((dtheta + std::numbers::pi) / (2.0 * std::numbers::pi), 0.0, 1.0) * last;
    dims = 3;
  } else {
    const double c[4] = {lo.x, lo.y, hi.x, hi.y};
    for (int k = 0; k < 4; ++k) coords[k] = std::clamp((c[k] + 1.0) * 0.5, 0.0, 1.0) * last;
    dims = 4;
  }
  const auto at = [&](const int* index) {
    size_t flat = 0;
    for (int k = 0; k < dims; ++k) flat = flat * size_t(n_) + size_t(index[k]);
    return double(values_[flat]);
  };
  int index[4];
  if (mode == CoverageTable::Nearest) {
    for (int k = 0; k < dims; ++k) index[k] = int(std::lround(coords[k]));
    return float(at(index));
  }
  // Multilinear over all parameters: 2^dims entries weighted by the product of the 1D weights.
  int base[4];
  double frac[4];
  for (int k = 0; k < dims; ++k) {
    base[k] = std::clamp(int(std::floor(coords[k])), 0, n_ - 2);
    frac[k] = std::clamp(coords[k] - double(base[k]), 0.0, 1.0);
  }
  double sum = 0.0;
  for (int corner = 0; corner < (1 << dims); ++corner) {
    double weight = 1.0;
    for (int k = 0; k < dims; ++k) {
      const int bit = (corner >> k) & 1;
      index[k] = base[k] + bit;
      weight *= bit ? frac[k] : 1.0 - frac[k];
    }
    if (weight != 0.0) sum += weight * at(index);
  }
  return float(sum);
}

float CoverageTableData::lookup(const dvec3& a, const dvec3& b, CoverageTable mode) const {
  dvec2 lo, hi;
  if (!clipToOutline(outline_, a, b, lo, hi)) return 0.0f;
  return lookupInside(lo, hi, mode);
}

const CoverageTableData& CoverageTableCache::get(const Light& light, int n) {
  const LightOutline outline =
      light.shape == LightShape::Rectangle ? LightOutline::Square : LightOutline::Disk;
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = tables_[{int(outline), n}];
  if (!slot) slot = std::make_unique<CoverageTableData>(outline, n);
  return *slot;
}

}  // namespace penumbra
