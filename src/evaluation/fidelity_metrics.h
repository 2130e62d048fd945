#pragma once
// The numbers of the fidelity page (docs/fidelity.md, `penumbra fidelity`): a technique's
// visibility against the oracle's, pooled over a scene's lights, over the pixels that show
// geometry ("covered") and over the oracle's penumbra (0 < oracle < 1); and the search for the
// oracle's equal-error ray count. Built on metrics/image_compare.h (MAE, RMSE, pixels over a
// tolerance); the 99th percentile is added here because the metrics module has none.
#include <cstddef>
#include <functional>
#include <vector>

#include <penumbra/core/image.h>

namespace penumbra {

struct ErrorStats {
  size_t pixels = 0;  // pixels in the set (over all lights)
  double mae = 0;     // mean |technique - oracle|
  double rmse = 0;
  double p99 = 0;     // 99th percentile of |technique - oracle| (nearest rank); 0 when empty
  // Mean of technique - oracle: negative where the technique is too dark (overlapping
  // occluders' penumbrae summed), positive where light leaks.
  double mean_signed = 0;
  size_t nonfinite = 0;  // NaN or infinite visibilities: a bug, counted and never averaged
};

struct FidelityError {
  ErrorStats covered;   // depth > 0 (a triangle shows there)
  ErrorStats penumbra;  // covered and 0 < oracle < 1
  double tolerance = 0.1;
  double fraction_over = 0;  // covered pixels with |error| > tolerance (strictly) / covered
};

// `technique[l]` and `oracle[l]` are light l's visibility buffers, `depth` the eye pass's
// (reversed-Z, 0 = background). Throws penumbra::Error when the light counts or sizes differ.
FidelityError fidelityError(const std::vector<Image<float>>& technique,
                            const std::vector<Image<float>>& oracle, const Image<float>& depth,
                            double tolerance = 0.1);

// Nearest-rank percentile (q in [0, 1]) of `values`, which it reorders; 0 when empty.
double percentileOf(std::vector<double>& values, double q);

// The oracle's error at each ray count of the search, filled lazily, smallest count first.
struct RayErrorPoint {
  int rays = 0;
  double penumbra_mae = 0;  // against the 1024-ray reference
  double ms = 0;            // the oracle's render time at this count (all lights)
};

// The ray counts searched for the equal-error count: 1, 2, 4, ..., max_rays (max_rays a power
// of two >= 1; throws otherwise).
std::vector<int> equalErrorRayCounts(int max_rays);

// The first point of `curve` (ordered by rays) whose penumbra MAE is at most `target`: the
// smallest ray count of the search reaching the technique's error. -1 when none does. With the
// oracle's noise the curve is not strictly monotone; "smallest N that reaches it" is the
// question a user asks, so the first is taken, not a fit.
int equalErrorIndex(const std::vector<RayErrorPoint>& curve, double target);

// Extends `curve` with `measure(rays)` over equalErrorRayCounts(max_rays) until a point reaches
// `target` or the counts run out, never measuring a count twice; returns equalErrorIndex.
int extendUntilReached(std::vector<RayErrorPoint>& curve, double target, int max_rays,
                       const std::function<RayErrorPoint(int rays)>& measure);

}  // namespace penumbra
