#include "shadows/coverage/coverage_table.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {
namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}  // namespace

CoverageTableData::CoverageTableData(LightOutline outline, int n) : outline_(outline), n_(n) {
  PENUMBRA_CHECK(n >= kMinCoverageTableSize && n <= kMaxCoverageTableSize,
                 "coverage table size {} is outside {}..{}", n, kMinCoverageTableSize,
                 kMaxCoverageTableSize);
  const size_t n1 = size_t(n);
  values_.resize(n1 * n1 * n1 * n1);
  parallelFor(n1 * n1, [&](size_t first) {
    const dvec2 q0 = point(int(first / n1), int(first % n1));
    float* out = values_.data() + first * n1 * n1;
    for (int i1 = 0; i1 < n; ++i1) {
      for (int j1 = 0; j1 < n; ++j1) {
        *out++ = float(insideFraction(outline_, q0, point(i1, j1)));
      }
    }
  });
}

dvec2 CoverageTableData::point(int i, int j) const {
  const double step = 1.0 / double(n_ - 1);
  if (outline_ == LightOutline::Disk) {
    const double r = double(i) * step, theta = kTwoPi * double(j) / double(n_);
    return dvec2(r * std::cos(theta), r * std::sin(theta));
  }
  return dvec2(2.0 * double(i) * step - 1.0, 2.0 * double(j) * step - 1.0);
}

dvec2 CoverageTableData::coordinates(const dvec2& q) const {
  const double last = double(n_ - 1);
  if (outline_ == LightOutline::Disk) {
    const double r = std::min(1.0, glm::length(q));
    double theta = std::atan2(q.y, q.x);
    if (theta < 0.0) theta += kTwoPi;
    // In [0, n); an angle that rounds up to 2 pi wraps to 0 here and in the lookups.
    double v = theta * double(n_) / kTwoPi;
    if (!(v < double(n_))) v = 0.0;
    return dvec2(r * last, v);
  }
  return dvec2(std::clamp((q.x + 1.0) * 0.5, 0.0, 1.0) * last,
               std::clamp((q.y + 1.0) * 0.5, 0.0, 1.0) * last);
}

float CoverageTableData::lookupInside(const dvec2& lo, const dvec2& hi,
                                      CoverageTable mode) const {
  const dvec2 c0 = coordinates(lo), c1 = coordinates(hi);
  const bool polar = outline_ == LightOutline::Disk;
  // Second index of a point: wraps for an angle, clamps for a coordinate.
  const auto second = [&](int j) { return polar ? (j % n_ + n_) % n_ : std::clamp(j, 0, n_ - 1); };
  if (mode == CoverageTable::Nearest) {
    return entry(int(std::lround(c0.x)), second(int(std::lround(c0.y))), int(std::lround(c1.x)),
                 second(int(std::lround(c1.y))));
  }
  // Quadlinear: the 16 entries around (c0, c1), weighted by the product of the four 1D
  // linear weights.
  int base[4];
  double frac[4];
  const double coords[4] = {c0.x, c0.y, c1.x, c1.y};
  for (int k = 0; k < 4; ++k) {
    const bool angle = polar && (k % 2 == 1);
    const double c = coords[k];
    int b = int(std::floor(c));
    if (!angle) b = std::clamp(b, 0, n_ - 2);
    base[k] = b;
    frac[k] = std::clamp(c - double(b), 0.0, 1.0);
  }
  double sum = 0.0;
  for (int corner = 0; corner < 16; ++corner) {
    int index[4];
    double weight = 1.0;
    for (int k = 0; k < 4; ++k) {
      const int bit = (corner >> k) & 1;
      index[k] = base[k] + bit;
      weight *= bit ? frac[k] : 1.0 - frac[k];
    }
    if (weight == 0.0) continue;
    sum += weight * double(entry(index[0], second(index[1]), index[2], second(index[3])));
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
