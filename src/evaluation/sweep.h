#pragma once
// The 2004 paper's evaluation (section 7, Figures 8-10), reproduced: for each scene one eye
// pass, then every wedge implementation x culling mode x culling-tile size, each run several
// times for a median time, with its exact work counters. Also the 2002 algorithm (no culling:
// the baseline of Figure 10a) and the ray-traced oracle (the "50x faster" claim).
//
// The evaluation module sits above render and metrics: it runs the frame's pieces
// (raster/eye_pass.h, renderShadows, render/shading_reuse.h) and compares visibilities with
// metrics/image_compare.h. evaluation/sweep_report.h summarises and writes what this returns;
// `penumbra bench` (apps/penumbra/bench_command.cpp) prints it and plots it;
// docs/reproducing-2004.md reads it against the paper.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/stats.h"
#include "shadows/technique.h"
#include "shadows/wedge_options.h"

namespace penumbra {

// The techniques the sweep runs, by their registered names (shadows/technique.h).
inline constexpr const char* kSweepThreePass = "wedge-3pass";
inline constexpr const char* kSweepSinglePass = "wedge-1pass";
inline constexpr const char* kSweep2002 = "wedge-2002";
inline constexpr const char* kSweepOracle = "reference";

struct SweepOptions {
  std::vector<std::string> scenes = {"columns", "fractal", "year2002"};
  int width = 640;  // the papers' image size
  int height = 427;
  int repeat = 5;  // timed runs per configuration; the median is reported
  std::vector<std::string> implementations = {kSweepThreePass,
                                                kSweepSinglePass};
  std::vector<CullMode> cull_modes = {CullMode::None, CullMode::ZMax, CullMode::Full};
  std::vector<int> tile_levels = {1, 2, 3, 4, 5, 6, 7, 8};  // tiles of 2^n x 2^n pixels
  bool original_2002 = true;  // one wedge-2002 configuration per scene (Figure 10a)
  int oracle_rays = 64;       // the oracle on `oracle_scene` (0: not run)
  std::string oracle_scene = "columns";
  int oracle_repeat = 1;  // the oracle's runs are slow (bench/README.md, Technique rows)
  bool smooth_falloff = false;
  // The 2004 paper's passes: every umbra pixel is depth-tested and written. true: the two-level
  // stencil of WedgeOptions::two_level_stencil (full culling only; stencil writes then
  // change with culling, which the paper's evaluation says they do not).
  bool two_level_stencil = false;
  bool simd = true;
  int threads = 0;             // 0: all cores
  bool show_progress = false;  // progress bar on a terminal (core/progress.h)
  // Called with one line per finished step (scene loaded, eye pass, mismatches); may be empty.
  std::function<void(const std::string&)> log;
};

// One configuration of one scene. Counters are those of the first run, summed over the scene's
// lights; every later run must give the same (counters_repeatable).
struct SweepRow {
  std::string scene;
  int width = 0, height = 0;
  int lights = 0;
  std::string kind = kSweepThreePass;  // a technique name (shadows/technique.h)
  CullMode cull = CullMode::None;  // wedge-2002 and the oracle: None
  int tile_level = 0;              // 0: not applicable (wedge-2002, oracle)
  int rays = 0;                    // the oracle's rays per pixel
  int runs = 0;
  Stats counters;  // time_ms empty; see pass_ms
  bool counters_repeatable = true;
  double technique_ms = 0, technique_ms_min = 0, technique_ms_max = 0;  // all lights, median
  // Process CPU time of the same runs (all threads), median: on a shared machine it moves less
  // with the neighbours' load than wall-clock time does.
  double technique_cpu_ms = 0;
  std::vector<std::pair<std::string, double>> pass_ms;  // median per pass name, run order
  double eye_ms = 0;    // the scene's eye pass and shading, medians (the same in every row of a
  double shade_ms = 0;  // scene): frame_ms = eye_ms + technique_ms + shade_ms
  double frame_ms = 0;
  // Culling must never change a pixel (2004 paper, section 4): pixels whose visibility differs
  // from this implementation's CullMode::None run at the first swept level (its first run when
  // None is not swept; -1: not compared, e.g. wedge-2002).
  int64_t cull_mismatch_pixels = -1;
  // Informational: pixels differing from wedge-3pass without culling, and the largest
  // difference (the implementations and the 2002 algorithm round differently in places).
  int64_t pixels_differing_from_3pass = -1;
  double max_diff_from_3pass = 0;

  // Figure 8's count: depth-buffer reads and LI-buffer writes of pixels.
  uint64_t memoryAccesses() const { return counters.z_reads + counters.stencil_writes; }
  // One read of a tile's (z-min, z-max) pair per culling test; none without culling. Counting
  // them is what gives a memory-optimal tile size: pixel reads alone only fall as tiles shrink.
  uint64_t tileRangeReads() const;
  uint64_t memoryAccessesWithTiles() const { return memoryAccesses() + tileRangeReads(); }
  double passMs(const std::string& name) const;  // 0 when the pass did not run
  std::string techniqueLabel() const;            // "wedge-3pass", "reference"
};

struct SweepResult {
  std::vector<SweepRow> rows;  // scene by scene, in SweepOptions order
  std::string cpu;             // machine, as stats_json.h's machineInfo
  int cores = 0;
  int threads = 0;
  std::string simd_target;
  std::string date;  // UTC, ISO 8601

  uint64_t cullMismatches() const;  // rows whose visibility changed with culling
  uint64_t unrepeatableRows() const;
};

// Runs the sweep. Throws penumbra::Error for bad options (unknown scene or technique, tile level
// outside 1..8, repeat < 1).
SweepResult runSweep(const SweepOptions& options);

}  // namespace penumbra
