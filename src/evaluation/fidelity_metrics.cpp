#include "evaluation/fidelity_metrics.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "metrics/image_compare.h"

namespace penumbra {
namespace {

// Sums of one pixel set over the lights, before the means.
struct Pooled {
  size_t pixels = 0, finite = 0, nonfinite = 0, over = 0;
  double sum_abs = 0, sum_sq = 0, sum_signed = 0;
  std::vector<double> errors;  // finite |a - b|, for the percentile

  void add(const Image<float>& a, const Image<float>& b, const Image<uint8_t>& mask,
           double tolerance) {
    // MAE, RMSE and the count over the tolerance as metrics/image_compare.h defines them; they
    // are means over the finite pixels, so they are turned back into sums to pool the lights.
    const ImageDifference d = compareImages(a, b, tolerance, &mask);
    const size_t finite_here = d.pixels - d.count_nonfinite;
    pixels += d.pixels;
    finite += finite_here;
    nonfinite += d.count_nonfinite;
    over += d.count_over_tolerance;
    sum_abs += d.mae * double(finite_here);
    sum_sq += d.rmse * d.rmse * double(finite_here);
    for (size_t i = 0; i < a.size(); ++i) {
      if (!mask[i]) continue;
      const double signed_error = double(a[i]) - double(b[i]);
      if (!std::isfinite(signed_error)) continue;
      errors.push_back(std::fabs(signed_error));
      sum_signed += signed_error;
    }
  }

  ErrorStats stats() {
    ErrorStats s;
    s.pixels = pixels;
    s.nonfinite = nonfinite;
    if (finite > 0) {
      s.mae = sum_abs / double(finite);
      s.rmse = std::sqrt(sum_sq / double(finite));
      s.mean_signed = sum_signed / double(finite);
    }
    s.p99 = percentileOf(errors, 0.99);
    return s;
  }
};

}  // namespace

double percentileOf(std::vector<double>& values, double q) {
  if (values.empty()) return 0.0;
  // Nearest rank: the smallest value with at least q of the values at or below it.
  const double rank = std::ceil(q * double(values.size()));
  const size_t k = size_t(std::clamp(rank, 1.0, double(values.size()))) - 1;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

FidelityError fidelityError(const std::vector<Image<float>>& technique,
                            const std::vector<Image<float>>& oracle, const Image<float>& depth,
                            double tolerance) {
  PENUMBRA_CHECK(technique.size() == oracle.size(),
                 "fidelity: {} technique visibility buffers but {} oracle ones", technique.size(),
                 oracle.size());
  Pooled covered, penumbra;
  for (size_t l = 0; l < oracle.size(); ++l) {
    const Image<float>& a = technique[l];
    const Image<float>& b = oracle[l];
    PENUMBRA_CHECK(a.width() == b.width() && a.height() == b.height() &&
                       b.width() == depth.width() && b.height() == depth.height(),
                   "fidelity: light {}: technique {}x{}, oracle {}x{}, depth {}x{} differ", l,
                   a.width(), a.height(), b.width(), b.height(), depth.width(), depth.height());
    // Reversed-Z depth: 0 is background, anything above shows a triangle.
    Image<uint8_t> covered_mask(b.width(), b.height(), uint8_t(0));
    Image<uint8_t> penumbra_mask(b.width(), b.height(), uint8_t(0));
    for (size_t i = 0; i < b.size(); ++i) {
      covered_mask[i] = depth[i] > 0.0f ? 1 : 0;
      penumbra_mask[i] = covered_mask[i] && b[i] > 0.0f && b[i] < 1.0f ? 1 : 0;
    }
    covered.add(a, b, covered_mask, tolerance);
    penumbra.add(a, b, penumbra_mask, tolerance);
  }
  FidelityError e;
  e.tolerance = tolerance;
  e.fraction_over = covered.pixels ? double(covered.over) / double(covered.pixels) : 0.0;
  e.covered = covered.stats();
  e.penumbra = penumbra.stats();
  return e;
}

std::vector<int> equalErrorRayCounts(int max_rays) {
  PENUMBRA_CHECK(max_rays >= 1 && max_rays <= (1 << 20) && (max_rays & (max_rays - 1)) == 0,
                 "fidelity: the largest searched ray count {} is not a power of two in 1..2^20",
                 max_rays);
  std::vector<int> counts;
  for (int n = 1; n <= max_rays; n *= 2) counts.push_back(n);
  return counts;
}

int equalErrorIndex(const std::vector<RayErrorPoint>& curve, double target) {
  for (size_t i = 0; i < curve.size(); ++i)
    if (curve[i].penumbra_mae <= target) return int(i);
  return -1;
}

int extendUntilReached(std::vector<RayErrorPoint>& curve, double target, int max_rays,
                       const std::function<RayErrorPoint(int rays)>& measure) {
  const int found = equalErrorIndex(curve, target);
  if (found >= 0) return found;
  for (int rays : equalErrorRayCounts(max_rays)) {
    if (!curve.empty() && rays <= curve.back().rays) continue;
    curve.push_back(measure(rays));
    if (curve.back().penumbra_mae <= target) return int(curve.size()) - 1;
  }
  return -1;
}

}  // namespace penumbra
