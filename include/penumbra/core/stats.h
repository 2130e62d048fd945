#pragma once
// Work counters, so the papers' figures can be plotted from them. The integer counters are
// exact and independent of the thread count: workers count into per-tile Stats that are summed
// in tile order. Two kinds: the shared counters below, which several techniques fill the same
// way, and the counters a technique or stage declares in its own folder for work only it does
// (CounterSpec), which it reports with its result.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra {

// The shared counters, declared once: X(name, description). The struct's fields, adding,
// comparing, the stats JSON, the sweep's CSV and the terminal summary all walk this list.
#define PENUMBRA_STATS_COUNTERS(X)                                                               \
  X(pixels_rasterized, "(primitive, pixel) pairs inside a primitive, on screen")                 \
  X(z_reads, "depth-buffer reads")                                                               \
  X(stencil_writes, "stencil or LI-buffer writes")                                               \
  X(tiles_tested, "(primitive, tile) pairs given to the tile test")                              \
  X(tiles_culled, "of those, the ones culled before any pixel")                                  \
  X(tiles_accepted, "of the others, the ones a shadow-volume polygon covers and passes whole: "  \
                    "one coarse stencil write, no pixel")                                        \
  X(silhouette_edges, "silhouette edges seen from the light centre")                             \
  X(wedges, "penumbra wedges built")                                                             \
  X(triangles, "triangles set up for rasterization (after clipping)")                            \
  X(rays, "oracle shadow rays (incl. ones its surface blocks untraced)")                         \
  /* Pixels whose depth point was tested against a wedge, and of those the ones truly inside */  \
  /* it. Their ratio is the distance from perfect culling (2004 paper, section 4). */            \
  X(penumbra_tests, "pixels whose point was tested against a wedge")                             \
  X(penumbra_inside, "of those, the ones inside the wedge")

// A counter that one technique or stage declares in its own folder, as a constant with static
// storage (`inline constexpr CounterSpec kTilesLit{"tiles_lit", "..."}`), and counts with
// Stats::count. Its name must not be a shared counter's.
struct CounterSpec {
  const char* name;
  const char* description;
};

// A pass that ran on other threads beside other passes (a parallel section) has a name ending
// in kConcurrentPass, e.g. "edges (concurrent)": its time overlaps theirs, so it is listed but
// not added to the frame's total. The section's wall time beyond the passes it ran beside is
// the pass kConcurrentWait (0 when they took longer), so the other passes add up to the wall
// time and no pass time is ever negative.
inline constexpr std::string_view kConcurrentPass = " (concurrent)";
inline constexpr const char* kConcurrentWait = "waiting for concurrent passes";
inline bool isConcurrentPass(std::string_view name) { return name.ends_with(kConcurrentPass); }

struct Stats {
#define PENUMBRA_STATS_FIELD(name, description) uint64_t name = 0;
  PENUMBRA_STATS_COUNTERS(PENUMBRA_STATS_FIELD)
#undef PENUMBRA_STATS_FIELD
  // The declared counters this frame reported, in the order they were first counted.
  std::vector<std::pair<const CounterSpec*, uint64_t>> declared;
  // Wall-clock milliseconds per named pass, in the order the passes ran. Not deterministic.
  std::vector<std::pair<std::string, double>> time_ms;

  // Adds `n` to a declared counter, entering it on first use: count(spec, 0) reports a counter
  // that stayed at zero.
  void count(const CounterSpec& spec, uint64_t n);
  // Any counter by its name, shared or declared; 0 for a name this frame did not count.
  uint64_t counter(std::string_view name) const;
  // Every counter: f(name, description, value), the shared ones in declaration order, then the
  // declared ones in the order they were first counted.
  template <class F>
  void forEachCounter(F&& f) const;

  // Adds the integer counters of `o` (not its timings).
  void addCounters(const Stats& o);
  // Adds counters and appends timings, for summing a technique's passes into a frame.
  void add(const Stats& o) {
    addCounters(o);
    time_ms.insert(time_ms.end(), o.time_ms.begin(), o.time_ms.end());
  }
  // The same value of every counter; a declared counter one side lacks counts as 0 there.
  bool sameCounters(const Stats& o) const;
  // The frame's wall time: every pass but the concurrent ones (isConcurrentPass).
  double totalMs() const {
    double t = 0;
    for (const auto& [name, ms] : time_ms)
      if (!isConcurrentPass(name)) t += ms;
    return t;
  }
};

// The shared counters as a table, in declaration order, for code that walks them by name.
struct StatsCounter {
  const char* name;
  const char* description;
  uint64_t Stats::*field;
};
inline constexpr StatsCounter kStatsCounters[] = {
#define PENUMBRA_STATS_ENTRY(name, description) {#name, description, &Stats::name},
    PENUMBRA_STATS_COUNTERS(PENUMBRA_STATS_ENTRY)
#undef PENUMBRA_STATS_ENTRY
};

inline void Stats::count(const CounterSpec& spec, uint64_t n) {
  for (auto& [declared_spec, value] : declared) {
    if (declared_spec == &spec || std::strcmp(declared_spec->name, spec.name) == 0) {
      value += n;
      return;
    }
  }
  declared.emplace_back(&spec, n);
}

inline uint64_t Stats::counter(std::string_view name) const {
  for (const StatsCounter& c : kStatsCounters)
    if (name == c.name) return this->*c.field;
  for (const auto& [spec, value] : declared)
    if (name == spec->name) return value;
  return 0;
}

template <class F>
void Stats::forEachCounter(F&& f) const {
  for (const StatsCounter& c : kStatsCounters) f(c.name, c.description, this->*c.field);
  for (const auto& [spec, value] : declared) f(spec->name, spec->description, value);
}

inline void Stats::addCounters(const Stats& o) {
  for (const StatsCounter& c : kStatsCounters) this->*c.field += o.*c.field;
  for (const auto& [spec, value] : o.declared) count(*spec, value);
}

inline bool Stats::sameCounters(const Stats& o) const {
  for (const StatsCounter& c : kStatsCounters)
    if (this->*c.field != o.*c.field) return false;
  for (const auto& [spec, value] : declared)
    if (o.counter(spec->name) != value) return false;
  for (const auto& [spec, value] : o.declared)
    if (counter(spec->name) != value) return false;
  return true;
}

}  // namespace penumbra
