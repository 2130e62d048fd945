#pragma once
// What a sweep (evaluation/sweep.h) measured, as the 2004 paper reports it: per-scene derived
// numbers (best tiles, speedups, single pass vs three pass), the CSV of every row and a markdown
// summary. Plotting the CSV is the caller's job (`penumbra bench` runs scripts/plot_sweep.py).
#include <iosfwd>
#include <string>
#include <vector>

#include "evaluation/sweep.h"

namespace penumbra {

// Derived numbers of one scene, for the summary and the comparison with the paper. Speedups
// are ratios of median times; "best" tiles minimise memory accesses or time with full culling.
struct SweepSceneSummary {
  std::string scene;
  struct Implementation {
    std::string kind = kSweepThreePass;  // a technique name (shadows/technique.h)
    int best_level_memory = 0;        // full culling, fewest z reads + stencil writes
    int best_level_memory_tiles = 0;  // same, tile z-range reads counted too
    int best_level_time = 0;          // full culling, fastest technique
    double restructured_speedup = 0;  // wedge-2002 time / this without culling (Figure 10a)
    double culling_speedup = 0;       // none / full at best_level_time, technique time
    double culling_speedup_pass = 0;  // same, on the penumbra pass (single pass: the pass)
    double zmax_speedup_pass = 0;     // none / zmax at z-max's fastest level, same pass
    double speedup_vs_2002 = 0;       // wedge-2002 time / this with full culling, best level
    // penumbra_tests / penumbra_inside per culling mode, at the levels above: the distance
    // from perfect culling (1: only pixels truly inside a wedge were tested).
    double none_tests_per_inside = 0;
    double zmax_tests_per_inside = 0;
    double full_tests_per_inside = 0;
  };
  std::vector<Implementation> implementations;
  // Single pass vs three pass, full culling, averaged over tiles 8x8..32x32 (section 7's range):
  // 1 - single / three of stencil writes, z reads, and their sum.
  double single_fewer_stencil_writes = 0;
  double single_fewer_z_reads = 0;
  double single_fewer_accesses = 0;
  // The same, had the three-pass umbra passes run without tile culling (as a GPU stencil pass
  // is counted when only its z-test is modelled): its umbra reads taken from CullMode::None.
  double single_fewer_accesses_unculled_umbra = 0;
  double oracle_frame_ratio = 0;  // oracle frame / fastest wedge frame (0: no oracle row)
};
// The reference configuration for "no culling": CullMode::None at the largest swept level, where
// culling tiles are no smaller than the rasterizer's bin tiles, so no extra splitting is timed.
std::vector<SweepSceneSummary> summarizeSweep(const SweepResult& result);

// One CSV line per row, with a header; columns documented in docs/reproducing-2004.md.
void writeSweepCsv(std::ostream& out, const SweepResult& result);
void writeSweepCsv(const std::string& path, const SweepResult& result);
// Markdown: machine, per-scene summary tables, mismatches. Used by `penumbra bench`.
std::string sweepSummaryMarkdown(const SweepResult& result);

}  // namespace penumbra
