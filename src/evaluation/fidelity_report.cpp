#include "evaluation/fidelity_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "evaluation/fidelity_failure_modes.h"
#include "render/frame_timing.h"

namespace penumbra {
namespace {

std::string raysText(const FidelityRow& row, int max_rays) {
  return row.equal_error_rays > 0 ? fmt::format("{}", row.equal_error_rays)
                                  : fmt::format("> {}", max_rays);
}

// Not reached within the search: the oracle at its largest searched count is still less
// accurate, so that count's time over the technique's is a lower bound of the ratio.
std::string ratioText(const FidelityScene& s, const FidelityRow& row, int max_rays) {
  if (row.equal_error_rays > 0) return fmt::format("{:.2g}x", row.speed_ratio);
  if (!s.curve.empty() && s.curve.back().rays == max_rays && row.technique_ms > 0)
    return fmt::format("> {:.2g}x", s.curve.back().ms / row.technique_ms);
  return "-";
}

// Per technique over the scenes where it ran: medians, and the smallest speed ratio (the
// scene where it is least worth it).
std::string summaryTable(const FidelityResult& r) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const FidelityRow*>> by_technique;
  for (const FidelityScene& s : r.scenes)
    for (const FidelityRow& row : s.rows) {
      if (!by_technique.count(row.technique)) order.push_back(row.technique);
      if (row.failure.empty()) by_technique[row.technique].push_back(&row);
      else by_technique[row.technique];
    }
  std::string out =
      "| technique | scenes | median penumbra MAE | worst penumbra MAE | median equal-error rays "
      "| smallest speed ratio | median speed ratio |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& t : order) {
    const auto& rows = by_technique[t];
    if (rows.empty()) {
      out += fmt::format("| {} | 0 | - | - | - | - | - |\n", t);
      continue;
    }
    std::vector<double> mae, rays, ratio;
    double worst = 0, smallest = -1;
    size_t unreached = 0;
    for (const FidelityRow* row : rows) {
      mae.push_back(row->error.penumbra.mae);
      worst = std::max(worst, row->error.penumbra.mae);
      if (row->equal_error_rays > 0) {
        rays.push_back(row->equal_error_rays);
        ratio.push_back(row->speed_ratio);
        smallest = smallest < 0 ? row->speed_ratio : std::min(smallest, row->speed_ratio);
      } else {
        ++unreached;
      }
    }
    out += fmt::format("| {} | {} | {:.4f} | {:.4f} | {}{} | {} | {} |\n", t, rows.size(),
                       medianOf(mae), worst, rays.empty() ? "-" : fmt::format("{:g}", medianOf(rays)),
                       unreached ? fmt::format(" ({} scene{} > {})", unreached,
                                               unreached == 1 ? "" : "s",
                                               r.options.max_search_rays)
                                 : "",
                       smallest < 0 ? "-" : fmt::format("{:.1f}x", smallest),
                       ratio.empty() ? "-" : fmt::format("{:.1f}x", medianOf(ratio)));
  }
  return out;
}

std::string sceneSection(const FidelityResult& r, const FidelityScene& s) {
  const FidelityOptions& o = r.options;
  std::string out = fmt::format("### {}\n\n", s.label);
  out += fmt::format("`{}`: {} triangles, {} light{}; oracle at {} rays: {:.0f} ms.\n", s.name,
                     s.triangles, s.lights, s.lights == 1 ? "" : "s", o.oracle_rays, s.oracle_ms);
  out += "Oracle with N rays against the reference (penumbra MAE, ms):";
  for (const RayErrorPoint& p : s.curve)
    out += fmt::format(" N={} {:.4f} {:.0f} ms;", p.rays, p.penumbra_mae, p.ms);
  if (s.curve.empty()) out += " (not needed)";
  out += "\n\n";
  out += fmt::format(
      "| technique | MAE | RMSE | p99 | penumbra MAE | penumbra RMSE | penumbra p99 | penumbra "
      "signed | off > {:g} | ms | equal-error rays | oracle ms at N | speed ratio |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      o.tolerance);
  for (const FidelityRow& row : s.rows) {
    if (!row.failure.empty()) {
      out += fmt::format("| {} | not run: {} ||||||||||||\n", row.technique, row.failure);
      continue;
    }
    const FidelityError& e = row.error;
    out += fmt::format(
        "| {} | {:.4f} | {:.4f} | {:.3f} | {:.4f} | {:.4f} | {:.3f} | {:+.4f} | {:.2f}% | {:.1f} | "
        "{} | {} | {} |\n",
        row.technique, e.covered.mae, e.covered.rmse, e.covered.p99, e.penumbra.mae,
        e.penumbra.rmse, e.penumbra.p99, e.penumbra.mean_signed, 100.0 * e.fraction_over, row.technique_ms,
        raysText(row, o.max_search_rays),
        row.equal_error_rays > 0 ? fmt::format("{:.0f}", row.equal_error_ms) : "-",
        ratioText(s, row, o.max_search_rays));
  }
  out += "\n";
  for (const FidelityRow& row : s.rows) {
    if (!row.same_as.empty())
      out += fmt::format("{}: the same image as {}, bit for bit.\n\n", row.technique, row.same_as);
    else if (!row.strip.empty())
      out += fmt::format("{}: ![{} on {}]({})\n\n", row.technique, row.technique, s.label,
                         row.strip);
  }
  return out;
}

}  // namespace

std::string fidelityMarkdown(const FidelityResult& r, const std::string& command) {
  const FidelityOptions& o = r.options;
  std::string out = "# Fidelity: the soft-shadow techniques against the ray-traced oracle\n\n";
  out += fmt::format(
      "Produced by `{}` on {} ({} hardware threads, {} worker threads, SIMD {}), {}, in {:.0f} s. "
      "The machine was shared with other builds: times are noisy, compare them within one "
      "table (every number of a scene comes from the same run).\n\n",
      command, r.cpu, r.cores, r.threads, r.simd_target, r.date, r.seconds);
  out += fmt::format(
      "Every soft technique that is not ray-traced, with its default options, renders each "
      "scene at {}x{}; the reference is the ray-traced oracle (`reference`) with {} jittered "
      "rays per pixel (seed {}). Per scene and technique, over all lights:\n\n"
      "- **MAE, RMSE, p99**: mean, root-mean-square and 99th-percentile (nearest rank) "
      "|technique - oracle| visibility error over the pixels that show geometry; the "
      "**penumbra** columns over the oracle's penumbra pixels only (0 < oracle < 1); "
      "**penumbra signed** the mean of technique - oracle there (negative: too dark).\n"
      "- **off > {:g}**: the share of pixels showing geometry off by more than {:g}.\n"
      "- **ms**: the technique alone, prepared beforehand, median of {} renders after a warm-up "
      "(all lights; no eye pass, no shading). The oracle's times are one render each, its BVH "
      "built beforehand.\n"
      "- **equal-error rays**: the smallest N of 1, 2, 4, ..., {} for which the oracle with N "
      "jittered rays (other random samples than the reference's) has a penumbra MAE against "
      "the reference at most the technique's; **oracle ms at N** its time; **speed ratio** = "
      "oracle ms at N / technique ms (above 1: the technique is worth it at equal error). "
      "\"> {}\" means no searched N was as accurate: the technique is closer to the reference "
      "than the reference's own noise lets the search resolve.\n\n"
      "Strips: technique | oracle | |error| heat map (black: none; brightest: {:g} or more), "
      "light 0, shrunk {}x.\n\n",
      o.width, o.height, o.oracle_rays, 1, o.tolerance, o.tolerance, o.timing_runs,
      o.max_search_rays, o.max_search_rays, o.heat_scale, o.strip_shrink);
  out += "## Summary\n\n" + summaryTable(r) + "\n";
  out += "## Failure modes\n\n" + fidelityFailureModes(r) + "\n";
  out += "## Scenes\n\n";
  for (const FidelityScene& s : r.scenes) out += sceneSection(r, s);
  if (!r.skipped.empty()) {
    out += "## Skipped scenes\n\n";
    for (const auto& [scene, why] : r.skipped) out += fmt::format("- `{}`: {}\n", scene, why);
    out += "\n";
  }
  return out;
}

std::string fidelityCsv(const FidelityResult& r) {
  std::ostringstream out;
  out << "scene,technique,failure,covered_pixels,mae,rmse,p99,penumbra_pixels,penumbra_mae,"
         "penumbra_rmse,penumbra_p99,penumbra_mean_signed,fraction_over,technique_ms,equal_error_rays,"
         "equal_error_ms,speed_ratio,oracle_ms\n";
  for (const FidelityScene& s : r.scenes)
    for (const FidelityRow& row : s.rows) {
      const FidelityError& e = row.error;
      std::string failure = row.failure;
      std::replace(failure.begin(), failure.end(), ',', ';');
      std::replace(failure.begin(), failure.end(), '\n', ' ');
      out << fmt::format("{},{},{},{},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},"
                         "{},{:.6g},{:.6g},{:.6g}\n",
                         s.label, row.technique, failure, e.covered.pixels, e.covered.mae,
                         e.covered.rmse, e.covered.p99, e.penumbra.pixels, e.penumbra.mae,
                         e.penumbra.rmse, e.penumbra.p99, e.penumbra.mean_signed, e.fraction_over,
                         row.technique_ms,
                         row.equal_error_rays, row.equal_error_ms, row.speed_ratio, s.oracle_ms);
    }
  return out.str();
}

}  // namespace penumbra
