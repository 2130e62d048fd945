#include "evaluation/sweep_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>

#include "core/error.h"

namespace penumbra {
namespace {

const SweepRow* findRow(const std::vector<const SweepRow*>& rows, const std::string& kind, CullMode cull,
                        int level) {
  for (const SweepRow* r : rows)
    if (r->kind == kind && r->cull == cull && r->tile_level == level) return r;
  return nullptr;
}

enum class Best { Time, Memory, MemoryWithTiles };

// The fastest (or least memory-hungry) level of one implementation and culling mode.
const SweepRow* bestRow(const std::vector<const SweepRow*>& rows, const std::string& kind, CullMode cull,
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
const SweepRow* uncullRow(const std::vector<const SweepRow*>& rows, const std::string& kind) {
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
std::string culledPass(const std::string& kind) {
  return kind == kSweepThreePass ? "penumbra" : "single-pass";
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

double testsPerInside(const SweepRow* r) {
  return r ? ratio(double(r->counters.penumbra_tests), double(r->counters.penumbra_inside))
           : 0.0;
}

// One implementation's figures on one scene (none without its unculled row); the frame time of
// its fastest fully culled row lowers fastest_wedge_frame.
std::optional<SweepSceneSummary::Implementation> summarizeImplementation(
    const std::vector<const SweepRow*>& rows, const std::string& kind, const SweepRow* original,
    double& fastest_wedge_frame) {
  const SweepRow* none = uncullRow(rows, kind);
  if (!none) return std::nullopt;
  SweepSceneSummary::Implementation impl;
  impl.kind = kind;
  const SweepRow* full_mem = bestRow(rows, kind, CullMode::Full, Best::Memory);
  const SweepRow* full_mem_tiles = bestRow(rows, kind, CullMode::Full, Best::MemoryWithTiles);
  const SweepRow* full = bestRow(rows, kind, CullMode::Full, Best::Time);
  const SweepRow* zmax = bestRow(rows, kind, CullMode::ZMax, Best::Time);
  const std::string pass = culledPass(kind);
  if (original) impl.restructured_speedup = ratio(original->technique_ms, none->technique_ms);
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
  return impl;
}

// Section 7: "in the range of tile sizes from 8x8 to 32x32 pixels, the single pass algorithm
// used about 5% fewer stencil buffer write accesses and 30-60% fewer depth buffer read
// accesses ... together, this saves 20-30%": the single pass's savings, averaged over the
// levels 3..5 both implementations have.
void summarizeSinglePassSavings(const std::vector<const SweepRow*>& rows,
                                SweepSceneSummary& s) {
  double writes = 0, reads = 0, accesses = 0, accesses_unculled = 0;
  int levels = 0;
  for (int level = 3; level <= 5; ++level) {
    const SweepRow* three = findRow(rows, kSweepThreePass, CullMode::Full, level);
    const SweepRow* single = findRow(rows, kSweepSinglePass, CullMode::Full, level);
    if (!three || !single) continue;
    writes += 1.0 - ratio(double(single->counters.stencil_writes),
                          double(three->counters.stencil_writes));
    reads += 1.0 - ratio(double(single->counters.z_reads), double(three->counters.z_reads));
    accesses += 1.0 - ratio(double(single->memoryAccesses()), double(three->memoryAccesses()));
    // Three-pass reads = umbra reads + penumbra reads (one per penumbra test).
    const SweepRow* three_none = findRow(rows, kSweepThreePass, CullMode::None, level);
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
}

}  // namespace

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
    const SweepRow* original = findRow(rows, kSweep2002, CullMode::None, 0);
    double fastest_wedge_frame = 0;
    for (const std::string kind : {kSweepThreePass, kSweepSinglePass}) {
      std::optional<SweepSceneSummary::Implementation> impl =
          summarizeImplementation(rows, kind, original, fastest_wedge_frame);
      if (impl) s.implementations.push_back(std::move(*impl));
    }
    summarizeSinglePassSavings(rows, s);
    for (const SweepRow* r : rows)
      if (r->kind == kSweepOracle && fastest_wedge_frame > 0)
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
  // The shared counters in the order they are declared (core/stats.h), every technique's own
  // counter any row reports, then the ones derived from them; the oracle's `rays` counter is
  // `shadow_rays` here, `rays` being its rays per pixel.
  std::vector<std::string> counters;
  for (const StatsCounter& counter : kStatsCounters) counters.push_back(counter.name);
  for (const SweepRow& r : result.rows) {
    for (const auto& [spec, value] : r.counters.declared) {
      if (std::find(counters.begin(), counters.end(), spec->name) == counters.end())
        counters.push_back(spec->name);
    }
  }
  out << "scene,width,height,lights,technique,cull,tile_level,tile_size,rays,runs";
  for (const std::string& counter : counters)
    out << "," << (counter == "rays" ? "shadow_rays" : counter);
  out << ",memory_accesses,tile_range_reads,memory_accesses_with_tiles,counters_repeatable,"
         "technique_ms,technique_ms_min,technique_ms_max,technique_cpu_ms";
  for (const std::string& pass : passes) out << "," << passColumn(pass);
  out << ",eye_ms,shade_ms,frame_ms,cull_mismatch_pixels,pixels_differing_from_3pass,"
         "max_diff_from_3pass\n";
  for (const SweepRow& r : result.rows) {
    out << fmt::format("{},{},{},{},{},{},{},{},{},{}", csvField(r.scene), r.width, r.height,
                       r.lights, r.techniqueLabel(), cullModeName(r.cull), r.tile_level,
                       r.tile_level > 0 ? 1 << r.tile_level : 0, r.rays, r.runs);
    for (const std::string& counter : counters) out << "," << r.counters.counter(counter);
    out << fmt::format(",{},{},{},", r.memoryAccesses(), r.tileRangeReads(),
                       r.memoryAccessesWithTiles());
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
          s.scene, i.kind, tile(i.best_level_memory),
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
    if (r.kind != kSweepOracle) continue;
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

}  // namespace penumbra
