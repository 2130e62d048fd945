// The coverage table of the 2003 soft shadow volumes (src/shadows/coverage/coverage_table.h)
// against the exact area it replaces: per light outline (disk: sphere and disk lights; square:
// rectangle lights), table size n (n^4 entries; the paper's 32) and lookup (nearest,
// quadlinear), the time of 4096 lookups of random segments clipped to the light, and as
// counters the mean and largest absolute error of those lookups against the exact area, in
// fractions of the light. CoverageTable/<outline>/exact times the exact area itself.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "shadows/coverage/coverage_table.h"
#include "shadows/coverage/shape_coverage.h"

namespace penumbra {
namespace {

struct Segments {
  std::vector<dvec2> lo, hi;
  std::vector<double> exact;
};

// 4096 random segments with end points in [-1.6, 1.6]^2, clipped to the light (misses redrawn).
const Segments& segments(LightOutline outline) {
  static std::map<int, Segments> cache;
  Segments& s = cache[int(outline)];
  if (!s.lo.empty()) return s;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  while (s.lo.size() < 4096) {
    dvec2 lo, hi;
    if (!clipToOutline(outline, dvec3(u(rng), u(rng), 1.0), dvec3(u(rng), u(rng), 1.0), lo, hi))
      continue;
    s.lo.push_back(lo);
    s.hi.push_back(hi);
    s.exact.push_back(insideFraction(outline, lo, hi));
  }
  return s;
}

const char* outlineName(LightOutline outline) {
  return outline == LightOutline::Disk ? "disk" : "square";
}

void tableLookups(benchmark::State& state, LightOutline outline, int n, CoverageTable mode) {
  const CoverageTableData table(outline, n);
  const Segments& s = segments(outline);
  double sum = 0.0, worst = 0.0;
  for (size_t k = 0; k < s.lo.size(); ++k) {
    const double e = std::fabs(double(table.lookupInside(s.lo[k], s.hi[k], mode)) - s.exact[k]);
    sum += e;
    worst = std::max(worst, e);
  }
  for (auto _ : state) {
    float total = 0.0f;
    for (size_t k = 0; k < s.lo.size(); ++k) total += table.lookupInside(s.lo[k], s.hi[k], mode);
    benchmark::DoNotOptimize(total);
  }
  state.counters["mean_error"] = sum / double(s.lo.size());
  state.counters["max_error"] = worst;
  state.counters["entries"] = double(table.entries());
}

void exactArea(benchmark::State& state, LightOutline outline) {
  const Segments& s = segments(outline);
  for (auto _ : state) {
    double total = 0.0;
    for (size_t k = 0; k < s.lo.size(); ++k) total += insideFraction(outline, s.lo[k], s.hi[k]);
    benchmark::DoNotOptimize(total);
  }
}

bool registerCoverageTableBenchmarks() {
  for (const LightOutline outline : {LightOutline::Disk, LightOutline::Square}) {
    for (const int n : {8, 16, 32, 48}) {
      for (const CoverageTable mode : {CoverageTable::Nearest, CoverageTable::Quadlinear}) {
        const std::string name = fmt::format("CoverageTable/{}/{}/{}", outlineName(outline), n,
                                             coverageTableName(mode));
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) {
          tableLookups(st, outline, n, mode);
        })->Unit(benchmark::kMicrosecond);
      }
    }
    const std::string name = fmt::format("CoverageTable/{}/exact", outlineName(outline));
    benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) {
      exactArea(st, outline);
    })->Unit(benchmark::kMicrosecond);
  }
  return true;
}

const bool coverage_table_registered = registerCoverageTableBenchmarks();

}  // namespace
}  // namespace penumbra
