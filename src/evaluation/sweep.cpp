#include "evaluation/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "metrics/image_compare.h"
#include "raster/eye_pass.h"
#include "raster/tile_kernels.h"
#include "render/frame_timing.h"
#include "render/shading_reuse.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"
#include "shadows/reference_options.h"
#include "shadows/wedge_options.h"

namespace penumbra {
namespace {

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

// One configuration while it is being measured: its runs' times, per pass, before the medians.
struct Pending {
  SweepRow row;
  TechniqueConfig options;
  std::vector<double> total_ms, cpu_ms;
  std::vector<std::string> pass_order;
  std::map<std::string, std::vector<double>> pass_runs;
};

struct Visibilities {
  std::vector<Image<float>> lights;
};

// Pixels whose visibility differs at all, summed over the lights, and the largest difference
// (metrics/image_compare.h: compareExact).
ExactDifference compareVisibility(const Visibilities& a, const Visibilities& b) {
  PENUMBRA_CHECK(a.lights.size() == b.lights.size(), "sweep: {} and {} visibility buffers",
                 a.lights.size(), b.lights.size());
  ExactDifference total;
  for (size_t l = 0; l < a.lights.size(); ++l) {
    const ExactDifference d = compareExact(a.lights[l], b.lights[l]);
    total.pixels += d.pixels;
    total.differing += d.differing;
    total.max_error = std::max(total.max_error, d.max_error);
  }
  return total;
}

// The only place where the sweep builds technique options: a row's configuration (kind,
// culling mode, tile level, oracle rays) plus the evaluation's fixed choices.
TechniqueConfig techniqueOptionsFor(const SweepOptions& o, const SweepRow& row) {
  TechniqueConfig config(row.kind);
  if (row.kind == kSweepOracle) {
    config.options<ReferenceOptions>().rays = row.rays;  // everything else as its defaults
    return config;
  }
  WedgeOptions& t = config.options<WedgeOptions>();
  t.cull = row.cull;
  if (row.tile_level > 0) t.tile_level = row.tile_level;  // wedge-2002: the default level
  t.smooth_falloff = o.smooth_falloff;
  t.two_level_stencil = o.two_level_stencil;
  t.umbra_tile_level = 0;  // the umbra pass at the swept tile size too
  return config;
}

// Runs the technique for every light of the scene once; counters summed, passes appended. The
// technique is prepared within the timed run, as the paper's comparison with the oracle counts
// the oracle's BVH build in its frame.
Stats runOnce(const TechniqueConfig& options, const RenderContext& context, const Scene& scene,
              const View& view, const EyeBuffers& eye, Visibilities* visibility, double& ms,
              double& cpu_ms) {
  Stats stats;
  if (visibility) visibility->lights.clear();
  const double cpu_start = cpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  for (const Light& light : scene.lights) {
    TechniqueResult result = renderShadows(options, scene, light, view, eye, context);
    stats.add(result.stats);
    if (visibility) visibility->lights.push_back(std::move(result.visibility));
  }
  ms = 1e3 * secondsSince(start);
  cpu_ms = 1e3 * (cpuSeconds() - cpu_start);
  return stats;
}

void record(Pending& p, const Stats& stats, double ms, double cpu_ms) {
  p.total_ms.push_back(ms);
  p.cpu_ms.push_back(cpu_ms);
  std::map<std::string, double> this_run;
  for (const auto& [name, pass_ms] : stats.time_ms) {
    if (!p.pass_runs.count(name) && !this_run.count(name)) p.pass_order.push_back(name);
    this_run[name] += pass_ms;
  }
  for (const auto& [name, pass_ms] : this_run) p.pass_runs[name].push_back(pass_ms);
  Stats counters = stats;
  counters.time_ms.clear();
  if (p.row.runs == 0) {
    p.row.counters = counters;
  } else if (!p.row.counters.sameCounters(counters)) {
    p.row.counters_repeatable = false;
  }
  ++p.row.runs;
}

SweepRow finish(Pending& p, double eye_ms, double shade_ms) {
  SweepRow row = std::move(p.row);
  row.technique_ms = medianOf(p.total_ms);
  row.technique_ms_min = *std::min_element(p.total_ms.begin(), p.total_ms.end());
  row.technique_ms_max = *std::max_element(p.total_ms.begin(), p.total_ms.end());
  row.technique_cpu_ms = medianOf(p.cpu_ms);
  for (const std::string& name : p.pass_order)
    row.pass_ms.emplace_back(name, medianOf(p.pass_runs[name]));
  row.eye_ms = eye_ms;
  row.shade_ms = shade_ms;
  row.frame_ms = eye_ms + row.technique_ms + shade_ms;
  return row;
}

void checkOptions(const SweepOptions& o) {
  PENUMBRA_CHECK(!o.scenes.empty(), "sweep: no scenes given");
  PENUMBRA_CHECK(o.width >= 1 && o.height >= 1, "sweep: image size {}x{} is empty", o.width,
                 o.height);
  PENUMBRA_CHECK(o.repeat >= 1, "sweep: repeat count {} is below 1", o.repeat);
  PENUMBRA_CHECK(o.oracle_repeat >= 1, "sweep: oracle repeat count {} is below 1", o.oracle_repeat);
  PENUMBRA_CHECK(o.oracle_rays >= 0 && o.oracle_rays <= 4096,
                 "sweep: oracle rays {} outside 0..4096", o.oracle_rays);
  for (int level : o.tile_levels)
    PENUMBRA_CHECK(level >= 1 && level <= 8, "sweep: tile level {} is outside 1..8 (2x2..256x256)",
                   level);
  for (const std::string& kind : o.implementations)
    PENUMBRA_CHECK(kind == kSweepThreePass || kind == kSweepSinglePass,
                   "sweep: '{}' is not a restructured wedge implementation (wedge-3pass, "
                   "wedge-1pass)",
                   kind);
}

// The configurations of one scene, in the order they are measured: CullMode::None first for
// every implementation (the other modes are compared against it), the three-pass
// implementation first, then the original 2002 algorithm if asked for.
std::vector<Pending> sweepConfigurations(const SweepOptions& o, const Scene& scene,
                                         const std::string& scene_name) {
  std::vector<CullMode> modes = o.cull_modes;
  std::stable_sort(modes.begin(), modes.end(), [](CullMode a, CullMode b) {
    return a == CullMode::None && b != CullMode::None;
  });
  std::vector<std::string> kinds = o.implementations;
  std::stable_sort(kinds.begin(), kinds.end(), [](const std::string& a, const std::string& b) {
    return a == kSweepThreePass && b != kSweepThreePass;
  });
  std::vector<Pending> configs;
  auto addConfig = [&](const std::string& kind, CullMode cull, int level) {
    Pending p;
    p.row.scene = scene.name.empty() ? scene_name : scene.name;
    p.row.width = o.width;
    p.row.height = o.height;
    p.row.lights = int(scene.lights.size());
    p.row.kind = kind;
    p.row.cull = cull;
    p.row.tile_level = level;
    p.options = techniqueOptionsFor(o, p.row);
    configs.push_back(std::move(p));
  };
  for (const std::string& kind : kinds)
    for (CullMode cull : modes)
      for (int level : o.tile_levels) addConfig(kind, cull, level);
  if (o.original_2002) addConfig(kSweep2002, CullMode::None, 0);
  return configs;
}

// What a configuration's first run is compared with: per implementation, its first
// CullMode::None run; the first three-pass CullMode::None run; and the visibility the shading
// is timed on.
struct SweepReferences {
  std::map<std::string, Visibilities> uncull;
  std::optional<Visibilities> three_pass;
  Visibilities shade;
};

// A configuration's first run against the references (taken from it where it is the first).
void compareFirstRun(Pending& p, Visibilities& visibility, SweepReferences& refs) {
  const bool restructured = p.row.kind != kSweep2002;
  if (restructured) {
    auto it = refs.uncull.find(p.row.kind);
    if (it == refs.uncull.end()) {
      // The reference itself: also checked against the other levels' None runs below.
      it = refs.uncull.emplace(p.row.kind, visibility).first;
    }
    p.row.cull_mismatch_pixels = int64_t(compareVisibility(it->second, visibility).differing);
  }
  if (!refs.three_pass && p.row.kind == kSweepThreePass && p.row.cull == CullMode::None)
    refs.three_pass = visibility;
  if (refs.three_pass) {
    const ExactDifference d = compareVisibility(*refs.three_pass, visibility);
    p.row.pixels_differing_from_3pass = int64_t(d.differing);
    p.row.max_diff_from_3pass = d.max_error;
  }
  if (refs.shade.lights.empty()) refs.shade = std::move(visibility);
}

// Shading is timed on a wedge visibility: the "frame" of Figure 9 is eye + technique + shade.
// The median of `repeat` runs (none without a visibility).
double medianShadeMs(const Scene& scene, const View& view, const EyeBuffers& eye,
                     const Visibilities& visibility, int repeat) {
  std::vector<double> shade_runs;
  if (!visibility.lights.empty()) {
    std::vector<const Image<float>*> pointers;
    for (const Image<float>& v : visibility.lights) pointers.push_back(&v);
    Image<vec3> color;
    for (int r = 0; r < repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      shadeFrameInto(scene, view, eye, pointers, color);
      shade_runs.push_back(1e3 * secondsSince(start));
    }
  }
  return medianOf(shade_runs);
}

// The oracle's row: oracle_repeat runs, the first compared with the three-pass reference.
SweepRow measureOracle(const SweepOptions& o, const std::string& row_scene, const Scene& scene,
                       const RenderContext& context, const View& view, const EyeBuffers& eye,
                       const std::optional<Visibilities>& three_pass, ProgressBar& bar,
                       double eye_ms, double shade_ms) {
  Pending p;
  p.row.scene = row_scene;
  p.row.width = o.width;
  p.row.height = o.height;
  p.row.lights = int(scene.lights.size());
  p.row.kind = kSweepOracle;
  p.row.rays = o.oracle_rays;
  p.options = techniqueOptionsFor(o, p.row);
  for (int r = 0; r < o.oracle_repeat; ++r) {
    double ms = 0, cpu_ms = 0;
    Visibilities visibility;
    const Stats stats =
        runOnce(p.options, context, scene, view, eye, r == 0 ? &visibility : nullptr, ms, cpu_ms);
    record(p, stats, ms, cpu_ms);
    bar.add();
    if (r == 0 && three_pass) {
      const ExactDifference d = compareVisibility(*three_pass, visibility);
      p.row.pixels_differing_from_3pass = int64_t(d.differing);
      p.row.max_diff_from_3pass = d.max_error;
    }
  }
  return finish(p, eye_ms, shade_ms);
}

void logSweepProblems(const std::vector<SweepRow>& rows,
                      const std::function<void(const std::string&)>& log) {
  for (const SweepRow& row : rows) {
    if (row.cull_mismatch_pixels > 0)
      log(fmt::format("MISMATCH: {} {} culling {} tiles {}x{}: {} pixels differ from culling none",
                      row.scene, row.techniqueLabel(), cullModeName(row.cull), 1 << row.tile_level,
                      1 << row.tile_level, row.cull_mismatch_pixels));
    if (!row.counters_repeatable)
      log(fmt::format("UNREPEATABLE: {} {} culling {} level {}: counters changed between runs",
                      row.scene, row.techniqueLabel(), cullModeName(row.cull), row.tile_level));
  }
}

// Rows of one scene, measured in rounds: every configuration once per round, so a neighbour's
// load on a shared machine falls on all of them alike instead of on a few.
std::vector<SweepRow> sweepScene(const SweepOptions& o, const std::string& scene_name,
                                 bool run_oracle) {
  const std::function<void(const std::string&)> log = [&](const std::string& line) {
    if (o.log) o.log(line);
  };
  const auto load_start = std::chrono::steady_clock::now();
  const Scene scene = loadScene(scene_name);
  const View view = scene.camera.makeView(o.width, o.height);
  log(fmt::format("{}: {} triangles, {} light(s), loaded in {:.1f} s", scene_name,
                  scene.triangleCount(), scene.lights.size(), secondsSince(load_start)));

  RenderContext context;
  context.simd = o.simd;
  std::vector<double> eye_runs;
  EyeBuffers eye;
  for (int r = 0; r < o.repeat; ++r) {
    Stats eye_stats;
    eye = renderEyePass(scene, view, eye_stats, o.simd);
    eye_runs.push_back(eye_stats.totalMs());
  }
  const double eye_ms = medianOf(eye_runs);

  std::vector<Pending> configs = sweepConfigurations(o, scene, scene_name);
  std::unique_ptr<ProgressBar> bar = std::make_unique<ProgressBar>(
      "sweep " + scene_name,
      uint64_t(configs.size()) * uint64_t(o.repeat) + (run_oracle ? uint64_t(o.oracle_repeat) : 0),
      o.show_progress);
  SweepReferences refs;
  for (int round = 0; round < o.repeat; ++round) {
    for (Pending& p : configs) {
      double ms = 0, cpu_ms = 0;
      Visibilities visibility;
      const bool first = round == 0;
      const Stats stats =
          runOnce(p.options, context, scene, view, eye, first ? &visibility : nullptr, ms, cpu_ms);
      record(p, stats, ms, cpu_ms);
      bar->add();
      if (first) compareFirstRun(p, visibility, refs);
    }
  }
  const double shade_ms = medianShadeMs(scene, view, eye, refs.shade, o.repeat);

  std::vector<SweepRow> rows;
  for (Pending& p : configs) rows.push_back(finish(p, eye_ms, shade_ms));
  if (run_oracle)
    rows.push_back(measureOracle(o, rows.empty() ? scene_name : rows.front().scene, scene,
                                 context, view, eye, refs.three_pass, *bar, eye_ms, shade_ms));
  bar->finish();
  logSweepProblems(rows, log);
  log(fmt::format("{}: eye pass {:.1f} ms, shading {:.1f} ms, {} configurations x {} runs",
                  scene_name, eye_ms, shade_ms, configs.size(), o.repeat));
  return rows;
}

}  // namespace

double SweepRow::passMs(const std::string& name) const {
  for (const auto& [pass, ms] : pass_ms)
    if (pass == name) return ms;
  return 0.0;
}

std::string SweepRow::techniqueLabel() const { return kind; }

uint64_t SweepRow::tileRangeReads() const {
  const bool culled = cull != CullMode::None && tile_level > 0;
  return culled ? counters.tiles_tested : 0;
}

uint64_t SweepResult::cullMismatches() const {
  uint64_t n = 0;
  for (const SweepRow& r : rows) n += r.cull_mismatch_pixels > 0;
  return n;
}

uint64_t SweepResult::unrepeatableRows() const {
  uint64_t n = 0;
  for (const SweepRow& r : rows) n += !r.counters_repeatable;
  return n;
}

SweepResult runSweep(const SweepOptions& options) {
  checkOptions(options);
  for (const std::string& name : options.scenes) {
    // Fail before measuring anything: a typo in the last scene must not cost the first ones.
    PENUMBRA_CHECK(isBuiltinScene(name) || std::filesystem::exists(name),
                   "sweep: unknown scene '{}' (built-in or a scene/mesh file)", name);
  }
  ThreadLimit limit(options.threads);
  SweepResult result;
  const MachineInfo machine = machineInfo();
  result.cpu = machine.cpu_model;
  result.cores = machine.cores;
  result.threads = workerCount();
  result.simd_target = options.simd ? simdTargetName() : "scalar";
  result.date = utcNow();
  bool oracle_done = false;
  for (const std::string& name : options.scenes) {
    const bool oracle = options.oracle_rays > 0 && !oracle_done && name == options.oracle_scene;
    oracle_done = oracle_done || oracle;
    std::vector<SweepRow> rows = sweepScene(options, name, oracle);
    result.rows.insert(result.rows.end(), std::make_move_iterator(rows.begin()),
                       std::make_move_iterator(rows.end()));
  }
  return result;
}

}  // namespace penumbra
