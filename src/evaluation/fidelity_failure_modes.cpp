#include "evaluation/fidelity_failure_modes.h"

#include <fmt/format.h>

#include <cmath>

namespace penumbra {
namespace {

struct FailureMode {
  const char* title;
  const char* scene;      // the scene label that shows it
  const char* technique;  // the technique pictured
  const char* peer;       // a technique without the failure, whose numbers are quoted beside
  const char* baseline;   // a scene without the failure, the same technique's numbers quoted ("")
  const char* text;
};

// Why each failure happens, with the sections that describe it. The numbers and pictures are
// the run's; the text says what to look for in them.
const FailureMode kModes[] = {
    {"Overlapping occluders", "year2002", "wedge-2002", "exact", "",
     "The wedge algorithms subtract each silhouette edge's share of the light from the light "
     "intensity buffer independently (2002 paper, section 8; the additive LI buffer). Where the "
     "penumbrae of two occluders overlap, both edges remove their share although they may hide "
     "the same part of the light, so the sum overshoots and the overlap goes too dark, down to "
     "black, where the oracle still sees part of the light. The coverage technique adds exact "
     "per-edge fractions but sums them the same way, so it keeps this error; `exact` counts the "
     "light samples each point sees and `heckbert-herf` averages hard shadows, so neither can "
     "overshoot. Look for the bright bands in the heat map where the digits' shadows overlap "
     "each other and the teapots'."},
    {"Silhouettes taken from the light centre", "terrain-low-light", "wedge-3pass", "exact", "",
     "Wedges, coverage and PCSS find the occluders' silhouette (or depth) once, from the light's "
     "centre (2002 paper, section 8; Funk 2004, section 4). On a rough height field under a "
     "low light many edges are silhouettes from one part of the light and not from another: "
     "the ridges' penumbrae are then built from the wrong edges, too light or too dark, and the "
     "error follows the terrain's ridges in the heat map. `exact` takes the silhouettes seen "
     "from each point and has no such error beyond its sample set's."},
    {"Large lights", "large-light", "wedge-3pass", "coverage", "spheres",
     "The spheres of `spheres` under a light five times larger. The wedges' umbra is the hard "
     "shadow from the centre widened by linear interpolation across each wedge (2002 paper, "
     "section 4); the wider the penumbra, the further that interpolation is from the true "
     "covered fraction and the more the single silhouette from the centre differs from those "
     "seen from the light's rim, so the error grows with the light's size. It is largest on the "
     "spheres' own terminators, where each sphere shadows itself and the silhouette from the "
     "centre is the terminator, and shows as bands across the floor's penumbrae. Coverage "
     "replaces the interpolation by each edge's exact covered fraction (2003 / Funk 2004) and "
     "keeps only the silhouette error."},
    {"PCSS: one depth map, an averaged blocker", "spheres", "pcss", "coverage", "",
     "PCSS (Fernando 2005) estimates the penumbra width from the average depth of the blockers "
     "found in the shadow map around the point, as if blocker and receiver were parallel planes, "
     "and filters a map rendered from the light's centre. Where several blockers at different "
     "heights are in the search region, or where the blocker is curved, the estimate is off, "
     "and the shadow map's texels and bias show, here most on the spheres' own terminators and "
     "along the penumbrae's outer rims; nothing in it computes the covered part of the light. It "
     "runs tuned as an engine would ship it, on scenes that shadow themselves: a constant and a "
     "slope-scaled depth bias (Unreal's ShadowBias and ShadowSlopeBias; Unity's depth bias, with "
     "a normal bias beside it; Urho3D's constant, slope-scaled and normal-offset bias), and the "
     "share of the light above the receiver's own plane; shadow-maps.md, \"Bias as engines ship "
     "it\", has the choices and the before and after."},
};

const FidelityRow* findRow(const FidelityResult& r, const std::string& scene,
                           const std::string& technique) {
  for (const FidelityScene& s : r.scenes)
    if (s.label == scene)
      for (const FidelityRow& row : s.rows)
        if (row.technique == technique && row.failure.empty()) return &row;
  return nullptr;
}

std::string numbers(const FidelityRow& row) {
  return fmt::format(
      "penumbra MAE {:.4f} (mean signed error {:+.4f}: {}), p99 {:.3f}, {:.2f}% of pixels off by "
      "more than {:g}",
      row.error.penumbra.mae, row.error.penumbra.mean_signed,
      // Below 0.005 the sign is the reference's noise, not a tendency of the technique.
      std::fabs(row.error.penumbra.mean_signed) < 0.005 ? "no tendency"
      : row.error.penumbra.mean_signed < 0              ? "darker than the oracle"
                                                        : "lighter than the oracle",
      row.error.penumbra.p99, 100.0 * row.error.fraction_over, row.error.tolerance);
}

}  // namespace

std::string fidelityFailureModes(const FidelityResult& r) {
  std::string out;
  for (const FailureMode& m : kModes) {
    out += fmt::format("### {}\n\n{}\n\n", m.title, m.text);
    const FidelityRow* row = findRow(r, m.scene, m.technique);
    if (!row) {
      out += fmt::format("(Not in this run: `{}` on `{}`.)\n\n", m.technique, m.scene);
      continue;
    }
    out += fmt::format("`{}` on `{}`: {}", m.technique, m.scene, numbers(*row));
    if (const FidelityRow* peer = findRow(r, m.scene, m.peer))
      out += fmt::format("; `{}` on the same frame: {}", m.peer, numbers(*peer));
    if (*m.baseline)
      if (const FidelityRow* base = findRow(r, m.baseline, m.technique))
        out += fmt::format("; `{}` on `{}`: {}", m.technique, m.baseline, numbers(*base));
    out += ".\n\n";
    if (!row->strip.empty())
      out += fmt::format("![{} on {}]({})\n\n", m.technique, m.scene, row->strip);
  }
  return out;
}

}  // namespace penumbra
