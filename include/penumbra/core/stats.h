#pragma once
// Work counters every technique fills the same way (DESIGN.md, "The technique contract"), so the
// papers' figures can be plotted from them. The integer counters are exact and independent of
// the thread count: workers count into per-tile Stats that are summed in tile order.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

// Every counter, declared once: X(name, description). The struct's fields, adding, comparing,
// the stats JSON, the sweep's CSV and the terminal summary all walk this list, so a technique
// that needs a new counter adds one line here.
#define PENUMBRA_STATS_COUNTERS(X)                                                               \
  X(pixels_rasterized, "(primitive, pixel) pairs inside a primitive, on screen")                 \
  X(z_reads, "depth-buffer reads")                                                               \
  X(stencil_writes, "stencil or LI-buffer writes")                                               \
  X(tiles_tested, "(primitive, tile) pairs given to the tile test")                              \
  X(tiles_culled, "of those, the ones culled before any pixel")                                  \
  X(tiles_accepted, "of the others, the ones a shadow-volume polygon covers and passes whole: "  \
                    "one coarse stencil write, no pixel")                                        \
  /* Hierarchical shadow volumes (thesis section 4.3): (volume, tile) pairs with a surface */    \
  /* that some triangle of the volume overlaps on screen, by how the tile was classified. */     \
  X(tiles_lit, "(volume, tile) pairs no volume triangle crosses, outside the volume")            \
  X(tiles_shadowed, "(volume, tile) pairs no volume triangle crosses, inside the volume")        \
  X(tiles_boundary, "(volume, tile) pairs a volume triangle crosses: drawn per pixel")           \
  X(silhouette_edges, "silhouette edges seen from the light centre")                             \
  X(wedges, "penumbra wedges built")                                                             \
  X(triangles, "triangles set up for rasterization (after clipping)")                            \
  X(rays, "oracle shadow rays (incl. ones its surface blocks untraced)")                         \
  /* Shadow maps: pixels whose point was looked up, and the ones a stencil-limited map */        \
  /* skipped as outside the light's frustum (Arvo & Aila 2003; thesis section 4.2). */           \
  X(shadow_map_lookups, "pixels whose point was looked up in a shadow map")                      \
  X(lookups_saved, "pixels a stencil-limited shadow map skipped: outside the light frustum")     \
  X(light_samples, "eye samples placed in the light's irregular z-buffer (alias-free)")          \
  X(sample_tests, "(occluder triangle, light-space sample) pairs tested (alias-free)")           \
  /* Pixels whose depth point was tested against a wedge, and of those the ones truly inside */  \
  /* it. Their ratio is the distance from perfect culling (2004 paper, section 4). */            \
  X(penumbra_tests, "pixels whose point was tested against a wedge")                             \
  X(penumbra_inside, "of those, the ones inside the wedge")

struct Stats {
#define PENUMBRA_STATS_FIELD(name, description) uint64_t name = 0;
  PENUMBRA_STATS_COUNTERS(PENUMBRA_STATS_FIELD)
#undef PENUMBRA_STATS_FIELD
  // Wall-clock milliseconds per named pass, in the order the passes ran. Not deterministic.
  std::vector<std::pair<std::string, double>> time_ms;

  // Adds the integer counters of `o` (not its timings).
  void addCounters(const Stats& o);
  // Adds counters and appends timings, for summing a technique's passes into a frame.
  void add(const Stats& o) {
    addCounters(o);
    time_ms.insert(time_ms.end(), o.time_ms.begin(), o.time_ms.end());
  }
  bool sameCounters(const Stats& o) const;
  double totalMs() const {
    double t = 0;
    for (const auto& [name, ms] : time_ms) t += ms;
    return t;
  }
};

// The counters as a table, in declaration order, for code that walks them by name.
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

inline void Stats::addCounters(const Stats& o) {
  for (const StatsCounter& c : kStatsCounters) this->*c.field += o.*c.field;
}

inline bool Stats::sameCounters(const Stats& o) const {
  for (const StatsCounter& c : kStatsCounters)
    if (this->*c.field != o.*c.field) return false;
  return true;
}

}  // namespace penumbra
