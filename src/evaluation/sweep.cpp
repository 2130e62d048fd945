#include "evaluation/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "raster/tile_kernels.h"
#include "render/eye_pass.h"
#include "render/shading_reuse.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"

namespace penumbra {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

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
  TechniqueOptions options;
  std::vector<double> total_ms, cpu_ms;
  std::vector<std::string> pass_order;
  std::map<std::string, std::vector<double>> pass_runs;
};

struct Visibilities {
  std::vector<Image<float>> lights;
};

// Pixels whose visibility differs at all (bit for bit), and the largest difference.
std::pair<int64_t, double> compareVisibility(const Visibilities& a, const Visibilities& b) {
  int64_t differing = 0;
  double largest = 0;
  for (size_t l = 0; l < a.lights.size() && l < b.lights.size(); ++l) {
    const Image<float>& x = a.lights[l];
    const Image<float>& y = b.lights[l];
    PENUMBRA_CHECK(x.size() == y.size(), "visibility images differ in size");
    for (size_t i = 0; i < x.size(); ++i) {
      if (x[i] == y[i]) continue;
      ++differing;
      largest = std::max(largest, double(std::fabs(x[i] - y[i])));
    }
  }
  return {differing, largest};
}

// Runs the technique for every light of the scene once; counters summed, passes appended.
Stats runOnce(const TechniqueOptions& options, const Scene& scene, const View& view,
              const EyeBuffers& eye, Visibilities* visibility, double& ms, double& cpu_ms) {
  Stats stats;
  if (visibility) visibility->lights.clear();
  const double cpu_start = cpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  for (const Light& light : scene.lights) {
    TechniqueResult result = renderShadows(options, scene, light, view, eye);
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
  row.technique_ms = median(p.total_ms);
  row.technique_ms_min = *std::min_element(p.total_ms.begin(), p.total_ms.end());
  row.technique_ms_max = *std::max_element(p.total_ms.begin(), p.total_ms.end());
  row.technique_cpu_ms = median(p.cpu_ms);
  for (const std::string& name : p.pass_order)
    row.pass_ms.emplace_back(name, median(p.pass_runs[name]));
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
  for (TechniqueKind kind : o.implementations)
    PENUMBRA_CHECK(kind == TechniqueKind::WedgeThreePass || kind == TechniqueKind::WedgeSinglePass,
                   "sweep: '{}' is not a restructured wedge implementation (wedge-3pass, "
                   "wedge-1pass)",
                   techniqueName(kind));
}

// Rows of one scene, measured in rounds: every configuration once per round, so a neighbour's
// load on a shared machine falls on all of them alike instead of on a few.
std::vector<SweepRow> sweepScene(const SweepOptions& o, const std::string& scene_name,
                                 bool run_oracle) {
  auto log = [&](const std::string& line) {
    if (o.log) o.log(line);
  };
  const auto load_start = std::chrono::steady_clock::now();
  const Scene scene = loadScene(scene_name);
  const View view = scene.camera.makeView(o.width, o.height);
  log(fmt::format("{}: {} triangles, {} light(s), loaded in {:.1f} s", scene_name,
                  scene.triangleCount(), scene.lights.size(), secondsSince(load_start)));

  std::vector<double> eye_runs;
  EyeBuffers eye;
  for (int r = 0; r < o.repeat; ++r) {
    Stats eye_stats;
    eye = renderEyePass(scene, view, eye_stats, o.simd);
    eye_runs.push_back(eye_stats.totalMs());
  }
  const double eye_ms = median(eye_runs);

  TechniqueOptions base;
  base.simd = o.simd;
  base.smooth_falloff = o.smooth_falloff;
  base.two_level_stencil = o.two_level_stencil;
  base.umbra_tile_level = 0;  // the umbra pass at the swept tile size too
  base.light_count = 1;  // each light has its own LI buffer (renderShadows per light)

  // CullMode::None first for every implementation: the other modes are compared against it.
  std::vector<CullMode> modes = o.cull_modes;
  std::stable_sort(modes.begin(), modes.end(), [](CullMode a, CullMode b) {
    return a == CullMode::None && b != CullMode::None;
  });
  std::vector<TechniqueKind> kinds = o.implementations;
  std::stable_sort(kinds.begin(), kinds.end(), [](TechniqueKind a, TechniqueKind b) {
    return a == TechniqueKind::WedgeThreePass && b != TechniqueKind::WedgeThreePass;
  });

  std::vector<Pending> configs;
  auto addConfig = [&](TechniqueKind kind, CullMode cull, int level) {
    Pending p;
    p.options = base;
    p.options.kind = kind;
    p.options.cull = cull;
    p.options.tile_level = level > 0 ? level : base.tile_level;
    p.row.scene = scene.name.empty() ? scene_name : scene.name;
    p.row.width = o.width;
    p.row.height = o.height;
    p.row.lights = int(scene.lights.size());
    p.row.kind = kind;
    p.row.cull = cull;
    p.row.tile_level = level;
    configs.push_back(std::move(p));
  };
  for (TechniqueKind kind : kinds)
    for (CullMode cull : modes)
      for (int level : o.tile_levels) addConfig(kind, cull, level);
  if (o.original_2002) addConfig(TechniqueKind::Wedge2002, CullMode::None, 0);

  std::unique_ptr<ProgressBar> bar = std::make_unique<ProgressBar>(
      "sweep " + scene_name,
      uint64_t(configs.size()) * uint64_t(o.repeat) + (run_oracle ? uint64_t(o.oracle_repeat) : 0),
      o.show_progress);

  std::map<TechniqueKind, Visibilities> uncull_reference;  // first CullMode::None run per kind
  std::optional<Visibilities> three_pass_reference;
  Visibilities shade_visibility;
  for (int round = 0; round < o.repeat; ++round) {
    for (Pending& p : configs) {
      double ms = 0, cpu_ms = 0;
      Visibilities visibility;
      const bool first = round == 0;
      const Stats stats =
          runOnce(p.options, scene, view, eye, first ? &visibility : nullptr, ms, cpu_ms);
      record(p, stats, ms, cpu_ms);
      bar->add();
      if (!first) continue;
      const bool restructured = p.row.kind != TechniqueKind::Wedge2002;
      if (restructured) {
        auto it = uncull_reference.find(p.row.kind);
        if (it == uncull_reference.end()) {
          // The reference itself: also checked against the other levels' None runs below.
          it = uncull_reference.emplace(p.row.kind, visibility).first;
        }
        p.row.cull_mismatch_pixels = compareVisibility(it->second, visibility).first;
      }
      if (!three_pass_reference && p.row.kind == TechniqueKind::WedgeThreePass &&
          p.row.cull == CullMode::None)
        three_pass_reference = visibility;
      if (three_pass_reference) {
        const auto [differing, largest] = compareVisibility(*three_pass_reference, visibility);
        p.row.pixels_differing_from_3pass = differing;
        p.row.max_diff_from_3pass = largest;
      }
      if (shade_visibility.lights.empty()) shade_visibility = std::move(visibility);
    }
  }

  // Shading is timed on a wedge visibility: the "frame" of Figure 9 is eye + technique + shade.
  std::vector<double> shade_runs;
  if (!shade_visibility.lights.empty()) {
    std::vector<const Image<float>*> pointers;
    for (const Image<float>& v : shade_visibility.lights) pointers.push_back(&v);
    Image<vec3> color;
    for (int r = 0; r < o.repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      shadeFrameInto(scene, view, eye, pointers, color);
      shade_runs.push_back(1e3 * secondsSince(start));
    }
  }
  const double shade_ms = median(shade_runs);

  std::vector<SweepRow> rows;
  for (Pending& p : configs) rows.push_back(finish(p, eye_ms, shade_ms));

  if (run_oracle) {
    Pending p;
    p.options.kind = TechniqueKind::Reference;
    p.options.rays = o.oracle_rays;
    p.options.simd = o.simd;
    p.row.scene = rows.empty() ? scene_name : rows.front().scene;
    p.row.width = o.width;
    p.row.height = o.height;
    p.row.lights = int(scene.lights.size());
    p.row.kind = TechniqueKind::Reference;
    p.row.rays = o.oracle_rays;
    for (int r = 0; r < o.oracle_repeat; ++r) {
      double ms = 0, cpu_ms = 0;
      Visibilities visibility;
      const Stats stats =
          runOnce(p.options, scene, view, eye, r == 0 ? &visibility : nullptr, ms, cpu_ms);
      record(p, stats, ms, cpu_ms);
      bar->add();
      if (r == 0 && three_pass_reference) {
        const auto [differing, largest] = compareVisibility(*three_pass_reference, visibility);
        p.row.pixels_differing_from_3pass = differing;
        p.row.max_diff_from_3pass = largest;
      }
    }
    rows.push_back(finish(p, eye_ms, shade_ms));
  }
  bar->finish();

  for (const SweepRow& row : rows) {
    if (row.cull_mismatch_pixels > 0)
      log(fmt::format("MISMATCH: {} {} culling {} tiles {}x{}: {} pixels differ from culling none",
                      row.scene, row.techniqueLabel(), cullModeName(row.cull), 1 << row.tile_level,
                      1 << row.tile_level, row.cull_mismatch_pixels));
    if (!row.counters_repeatable)
      log(fmt::format("UNREPEATABLE: {} {} culling {} level {}: counters changed between runs",
                      row.scene, row.techniqueLabel(), cullModeName(row.cull), row.tile_level));
  }
  log(fmt::format("{}: eye pass {:.1f} ms, shading {:.1f} ms, {} configurations x {} runs",
                  scene_name, eye_ms, shade_ms, configs.size(), o.repeat));
  return rows;
}

const SweepRow* findRow(const std::vector<const SweepRow*>& rows, TechniqueKind kind, CullMode cull,
                        int level) {
  for (const SweepRow* r : rows)
    if (r->kind == kind && r->cull == cull && r->tile_level == level) return r;
  return nullptr;
}

enum class Best { Time, Memory, MemoryWithTiles };

// The fastest (or least memory-hungry) level of one implementation and culling mode.
const SweepRow* bestRow(const std::vector<const SweepRow*>& rows, TechniqueKind kind, CullMode cull,
                        Best by) {
  const SweepRow* best = nullptr;
  for (const SweepRow* r : rows) {
    if (r->kind != kind || r->cull != cull || r->tile_level == 0) continue;
    bool better = !best;
    if (best) {
      switch (by) {
        case Best::Time:
          better = r->technique_ms < best->technique_ms;
          break;
        case Best::Memory:
          better = r->memoryAccesses() < best->memoryAccesses();
          break;
        case Best::MemoryWithTiles:
          better = r->memoryAccessesWithTiles() < best->memoryAccessesWithTiles();
          break;
      }
    }
    if (better) best = r;
  }
  return best;
}

// The reference "no culling" row: None at the largest level (no tile splitting timed).
const SweepRow* uncullRow(const std::vector<const SweepRow*>& rows, TechniqueKind kind) {
  const SweepRow* best = nullptr;
  for (const SweepRow* r : rows)
    if (r->kind == kind && r->cull == CullMode::None && r->tile_level > 0 &&
        (!best || r->tile_level > best->tile_level))
      best = r;
  return best;
}

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

// The pass that culling speeds up: the penumbra pass of the three-pass implementation, the one
// pass of the single-pass implementation.
std::string culledPass(TechniqueKind kind) {
  return kind == TechniqueKind::WedgeThreePass ? "penumbra" : "single-pass";
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string passColumn(const std::string& pass) {
  std::string name = pass;
  for (char& c : name)
    if (c == '-' || c == ' ') c = '_';
  return name + "_ms";
}

}  // namespace

double SweepRow::passMs(const std::string& name) const {
  for (const auto& [pass, ms] : pass_ms)
    if (pass == name) return ms;
  return 0.0;
}

std::string SweepRow::techniqueLabel() const { return techniqueName(kind); }

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

std::vector<SweepSceneSummary> summarizeSweep(const SweepResult& result) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const SweepRow*>> by_scene;
  for (const SweepRow& r : result.rows) {
    if (!by_scene.count(r.scene)) order.push_back(r.scene);
    by_scene[r.scene].push_back(&r);
  }
  std::vector<SweepSceneSummary> summaries;
  for (const std::string& scene : order) {
    const std::vector<const SweepRow*>& rows = by_scene[scene];
    SweepSceneSummary s;
    s.scene = scene;
    const SweepRow* original = findRow(rows, TechniqueKind::Wedge2002, CullMode::None, 0);
    double fastest_wedge_frame = 0;
    for (TechniqueKind kind : {TechniqueKind::WedgeThreePass, TechniqueKind::WedgeSinglePass}) {
      const SweepRow* none = uncullRow(rows, kind);
      if (!none) continue;
      SweepSceneSummary::Implementation impl;
      impl.kind = kind;
      const SweepRow* full_mem = bestRow(rows, kind, CullMode::Full, Best::Memory);
      const SweepRow* full_mem_tiles = bestRow(rows, kind, CullMode::Full, Best::MemoryWithTiles);
      const SweepRow* full = bestRow(rows, kind, CullMode::Full, Best::Time);
      const SweepRow* zmax = bestRow(rows, kind, CullMode::ZMax, Best::Time);
      const std::string pass = culledPass(kind);
      if (original) impl.restructured_speedup = ratio(original->technique_ms, none->technique_ms);
      auto testsPerInside = [](const SweepRow* r) {
        return r ? ratio(double(r->counters.penumbra_tests), double(r->counters.penumbra_inside))
                 : 0.0;
      };
      impl.none_tests_per_inside = testsPerInside(none);
      if (full_mem) impl.best_level_memory = full_mem->tile_level;
      if (full_mem_tiles) impl.best_level_memory_tiles = full_mem_tiles->tile_level;
      if (full) {
        impl.best_level_time = full->tile_level;
        impl.culling_speedup = ratio(none->technique_ms, full->technique_ms);
        impl.culling_speedup_pass = ratio(none->passMs(pass), full->passMs(pass));
        impl.full_tests_per_inside = testsPerInside(full);
        if (original) impl.speedup_vs_2002 = ratio(original->technique_ms, full->technique_ms);
        if (fastest_wedge_frame == 0 || full->frame_ms < fastest_wedge_frame)
          fastest_wedge_frame = full->frame_ms;
      }
      if (zmax) {
        impl.zmax_speedup_pass = ratio(none->passMs(pass), zmax->passMs(pass));
        impl.zmax_tests_per_inside = testsPerInside(zmax);
      }
      s.implementations.push_back(impl);
    }
    // Section 7: "in the range of tile sizes from 8x8 to 32x32 pixels, the single pass
    // algorithm used about 5% fewer stencil buffer write accesses and 30-60% fewer depth buffer
    // read accesses ... together, this saves 20-30%".
    double writes = 0, reads = 0, accesses = 0, accesses_unculled = 0;
    int levels = 0;
    for (int level = 3; level <= 5; ++level) {
      const SweepRow* three = findRow(rows, TechniqueKind::WedgeThreePass, CullMode::Full, level);
      const SweepRow* single = findRow(rows, TechniqueKind::WedgeSinglePass, CullMode::Full, level);
      if (!three || !single) continue;
      writes += 1.0 - ratio(double(single->counters.stencil_writes),
                            double(three->counters.stencil_writes));
      reads += 1.0 - ratio(double(single->counters.z_reads), double(three->counters.z_reads));
      accesses += 1.0 - ratio(double(single->memoryAccesses()), double(three->memoryAccesses()));
      // Three-pass reads = umbra reads + penumbra reads (one per penumbra test).
      const SweepRow* three_none =
          findRow(rows, TechniqueKind::WedgeThreePass, CullMode::None, level);
      if (three_none) {
        const double umbra_unculled =
            double(three_none->counters.z_reads - three_none->counters.penumbra_tests);
        const double three_unculled = umbra_unculled + double(three->counters.penumbra_tests) +
                                      double(three->counters.stencil_writes);
        accesses_unculled += 1.0 - ratio(double(single->memoryAccesses()), three_unculled);
      }
      ++levels;
    }
    if (levels > 0) {
      s.single_fewer_stencil_writes = writes / levels;
      s.single_fewer_z_reads = reads / levels;
      s.single_fewer_accesses = accesses / levels;
      s.single_fewer_accesses_unculled_umbra = accesses_unculled / levels;
    }
    for (const SweepRow* r : rows)
      if (r->kind == TechniqueKind::Reference && fastest_wedge_frame > 0)
        s.oracle_frame_ratio = ratio(r->frame_ms, fastest_wedge_frame);
    summaries.push_back(std::move(s));
  }
  return summaries;
}

void writeSweepCsv(std::ostream& out, const SweepResult& result) {
  std::vector<std::string> passes;
  for (const SweepRow& r : result.rows)
    for (const auto& [name, ms] : r.pass_ms)
      if (std::find(passes.begin(), passes.end(), name) == passes.end()) passes.push_back(name);
  out << "scene,width,height,lights,technique,cull,tile_level,tile_size,rays,runs,"
         "pixels_rasterized,z_reads,stencil_writes,memory_accesses,tiles_tested,tiles_culled,"
         "tiles_accepted,tile_range_reads,memory_accesses_with_tiles,penumbra_tests,"
         "penumbra_inside,"
         "silhouette_edges,wedges,triangles,shadow_rays,counters_repeatable,technique_ms,"
         "technique_ms_min,technique_ms_max,technique_cpu_ms";
  for (const std::string& pass : passes) out << "," << passColumn(pass);
  out << ",eye_ms,shade_ms,frame_ms,cull_mismatch_pixels,pixels_differing_from_3pass,"
         "max_diff_from_3pass\n";
  for (const SweepRow& r : result.rows) {
    const Stats& c = r.counters;
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},", csvField(r.scene), r.width, r.height,
                       r.lights, r.techniqueLabel(), cullModeName(r.cull), r.tile_level,
                       r.tile_level > 0 ? 1 << r.tile_level : 0, r.rays, r.runs);
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},", c.pixels_rasterized,
                       c.z_reads, c.stencil_writes, r.memoryAccesses(), c.tiles_tested,
                       c.tiles_culled, c.tiles_accepted, r.tileRangeReads(),
                       r.memoryAccessesWithTiles(), c.penumbra_tests,
                       c.penumbra_inside, c.silhouette_edges, c.wedges, c.triangles, c.rays);
    out << fmt::format("{},{:.4f},{:.4f},{:.4f},{:.4f}", r.counters_repeatable ? 1 : 0,
                       r.technique_ms, r.technique_ms_min, r.technique_ms_max, r.technique_cpu_ms);
    for (const std::string& pass : passes) out << fmt::format(",{:.4f}", r.passMs(pass));
    out << fmt::format(",{:.4f},{:.4f},{:.4f},{},{},{:.6g}\n", r.eye_ms, r.shade_ms, r.frame_ms,
                       r.cull_mismatch_pixels, r.pixels_differing_from_3pass,
                       r.max_diff_from_3pass);
  }
}

void writeSweepCsv(const std::string& path, const SweepResult& result) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  std::ofstream out(path, std::ios::binary);
  PENUMBRA_CHECK(out.good(), "cannot open '{}' for writing", path);
  writeSweepCsv(out, result);
  out.close();
  PENUMBRA_CHECK(!out.fail(), "cannot write '{}'", path);
}

std::string sweepSummaryMarkdown(const SweepResult& result) {
  std::string md =
      fmt::format("Machine: {}, {} hardware threads, {} worker threads, SIMD {}, {}.\n", result.cpu,
                  result.cores, result.threads, result.simd_target, result.date);
  if (!result.rows.empty()) {
    const SweepRow& r = result.rows.front();
    md += fmt::format("Image {}x{}, median of {} runs per configuration.\n", r.width, r.height,
                      r.runs);
  }
  const std::vector<SweepSceneSummary> summaries = summarizeSweep(result);
  md +=
      "\n| scene | implementation | best tile: memory (pixels / with tile reads) | best tile: "
      "time | restructured vs 2002, no culling | culling full vs none: technique / culled pass | "
      "z-max only vs none (pass) | full culling vs 2002 | tests per inside pixel: none / zmax "
      "/ full |\n|---|---|---|---|---|---|---|---|---|\n";
  auto tile = [](int level) {
    return level > 0 ? fmt::format("{0}x{0}", 1 << level) : std::string("-");
  };
  for (const SweepSceneSummary& s : summaries) {
    for (const auto& i : s.implementations) {
      md += fmt::format(
          "| {} | {} | {} / {} | {} | {:.2f}x | {:.2f}x / {:.2f}x | {:.2f}x | {:.2f}x | {:.1f} / "
          "{:.1f} / {:.2f} |\n",
          s.scene, techniqueName(i.kind), tile(i.best_level_memory),
          tile(i.best_level_memory_tiles), tile(i.best_level_time), i.restructured_speedup,
          i.culling_speedup, i.culling_speedup_pass, i.zmax_speedup_pass, i.speedup_vs_2002,
          i.none_tests_per_inside, i.zmax_tests_per_inside, i.full_tests_per_inside);
    }
  }
  md +=
      "\nSingle pass vs three pass, full culling, mean over tiles 8x8..32x32:\n\n"
      "| scene | fewer stencil writes | fewer z reads | fewer memory accesses | same, three-pass "
      "umbra unculled |\n|---|---|---|---|---|\n";
  for (const SweepSceneSummary& s : summaries)
    md += fmt::format("| {} | {:.1f} % | {:.1f} % | {:.1f} % | {:.1f} % |\n", s.scene,
                      100 * s.single_fewer_stencil_writes, 100 * s.single_fewer_z_reads,
                      100 * s.single_fewer_accesses, 100 * s.single_fewer_accesses_unculled_umbra);
  for (const SweepRow& r : result.rows) {
    if (r.kind != TechniqueKind::Reference) continue;
    for (const SweepSceneSummary& s : summaries)
      if (s.scene == r.scene)
        md += fmt::format(
            "\nOracle, {} rays, {}: technique {:.1f} ms, frame {:.1f} ms; the fastest wedge frame "
            "(full culling) is {:.1f}x faster.\n",
            r.rays, r.scene, r.technique_ms, r.frame_ms, s.oracle_frame_ratio);
  }
  const uint64_t mismatches = result.cullMismatches();
  md +=
      mismatches == 0
          ? "\nCulling changed no pixel: every culling mode gave the visibility of culling none.\n"
          : fmt::format(
                "\n**MISMATCH: {} configuration(s) changed visibility with culling** "
                "(column cull_mismatch_pixels).\n",
                mismatches);
  if (result.unrepeatableRows() > 0)
    md += fmt::format("\n**{} configuration(s) gave different counters on different runs.**\n",
                      result.unrepeatableRows());
  return md;
}

std::string plotScriptPath() { return std::string(PENUMBRA_SOURCE_DIR) + "/scripts/plot_sweep.py"; }

bool plottingAvailable() {
  if (!std::filesystem::exists("/usr/bin/python3") || !std::filesystem::exists(plotScriptPath()))
    return false;
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

std::string plotCommand(const std::string& csv_path, const std::string& out_dir) {
  return fmt::format("/usr/bin/python3 '{}' --csv '{}' --out '{}'", plotScriptPath(), csv_path,
                     out_dir);
}

}  // namespace penumbra
