#pragma once
// Work counters every technique fills the same way (DESIGN.md, "The technique contract"), so the
// papers' figures can be plotted from them. The integer counters are exact and independent of
// the thread count: workers count into per-tile Stats that are summed in tile order.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

struct Stats {
  uint64_t pixels_rasterized = 0;  // (primitive, pixel) pairs inside a primitive, on screen
  uint64_t z_reads = 0;            // depth-buffer reads
  uint64_t stencil_writes = 0;     // stencil or LI-buffer writes
  uint64_t tiles_tested = 0;       // (primitive, tile) pairs given to the tile test
  uint64_t tiles_culled = 0;       // of those, the ones culled before any pixel
  uint64_t tiles_accepted = 0;     // of the others, the ones a shadow-volume polygon covers and
                                   // passes whole: one coarse stencil write, no pixel
  uint64_t silhouette_edges = 0;   // silhouette edges seen from the light centre
  uint64_t wedges = 0;             // penumbra wedges built
  uint64_t triangles = 0;          // triangles set up for rasterization (after clipping)
  uint64_t rays = 0;               // oracle shadow rays (incl. ones its surface blocks untraced)
  // Penumbra wedges: pixels whose depth point was tested against a wedge, and of those the ones
  // truly inside it. Their ratio is the distance from perfect culling (2004 paper, section 4).
  uint64_t penumbra_tests = 0;
  uint64_t penumbra_inside = 0;
  // Wall-clock milliseconds per named pass, in the order the passes ran. Not deterministic.
  std::vector<std::pair<std::string, double>> time_ms;

  // Adds the integer counters of `o` (not its timings).
  void addCounters(const Stats& o) {
    pixels_rasterized += o.pixels_rasterized;
    z_reads += o.z_reads;
    stencil_writes += o.stencil_writes;
    tiles_tested += o.tiles_tested;
    tiles_culled += o.tiles_culled;
    tiles_accepted += o.tiles_accepted;
    silhouette_edges += o.silhouette_edges;
    wedges += o.wedges;
    triangles += o.triangles;
    rays += o.rays;
    penumbra_tests += o.penumbra_tests;
    penumbra_inside += o.penumbra_inside;
  }
  // Adds counters and appends timings, for summing a technique's passes into a frame.
  void add(const Stats& o) {
    addCounters(o);
    time_ms.insert(time_ms.end(), o.time_ms.begin(), o.time_ms.end());
  }
  bool sameCounters(const Stats& o) const {
    return pixels_rasterized == o.pixels_rasterized && z_reads == o.z_reads &&
           stencil_writes == o.stencil_writes && tiles_tested == o.tiles_tested &&
           tiles_culled == o.tiles_culled && tiles_accepted == o.tiles_accepted &&
           silhouette_edges == o.silhouette_edges &&
           wedges == o.wedges && triangles == o.triangles &&
           penumbra_tests == o.penumbra_tests && penumbra_inside == o.penumbra_inside && rays == o.rays;
  }
  double totalMs() const {
    double t = 0;
    for (const auto& [name, ms] : time_ms) t += ms;
    return t;
  }
};

}  // namespace penumbra
