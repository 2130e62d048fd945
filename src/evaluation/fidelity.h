#pragma once
// The fidelity page (issue 9 item 6, issue 12's PCSS row): every soft technique that is not
// ray-traced, on every scene, against the ray-traced oracle at many rays, with the error
// numbers of evaluation/fidelity_metrics.h, a frame time per technique, the oracle's
// equal-error ray count and its time, and an image strip (technique | oracle | error heat map)
// per row. evaluation/fidelity_report.h writes the page; `penumbra fidelity`
// (apps/penumbra/fidelity_command.cpp) runs it.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "evaluation/fidelity_metrics.h"

namespace penumbra {

struct FidelityOptions {
  // Built-in scene names or scene file paths (fidelityScenes resolves the default list).
  std::vector<std::string> scenes;
  // Technique names; empty: every registered technique whose traits are soft and not
  // ray-traced (fidelityTechniques()).
  std::vector<std::string> techniques;
  int width = 320;
  int height = 214;
  int oracle_rays = 1024;     // the reference every error is measured against (seed 1)
  int max_search_rays = 512;  // equal-error search over 1, 2, 4, ..., this (a power of two)
  int timing_runs = 3;        // timed renders of each prepared technique; the median is shown
  double tolerance = 0.1;     // "off by more than" this
  // Where the strips go ("" : none), and the factor they are shrunk by (1, 2 or 4: box filter)
  // to keep the page's images small.
  std::string strip_dir;
  std::string strip_prefix;  // prepended to strip file names in the rows (the page's relative path)
  int strip_shrink = 2;
  float heat_scale = 0.25f;  // error drawn brightest in every heat map, so strips compare
  bool simd = true;
  int threads = 0;             // 0: all cores
  bool show_progress = false;  // progress bar on a terminal (core/progress.h)
  std::function<void(const std::string&)> log;  // one line per finished step; may be empty
};

struct FidelityRow {
  std::string technique;
  std::string failure;  // non-empty: the technique refused the scene (e.g. a light shape); no numbers
  FidelityError error;
  double technique_ms = 0;  // median over timing_runs renders, all lights, prepared beforehand
  int equal_error_rays = -1;  // smallest searched oracle ray count at most this penumbra MAE; -1: none
  double equal_error_ms = 0;  // the oracle's time at that count
  double speed_ratio = 0;     // equal_error_ms / technique_ms (0 when no count reached it)
  std::string strip;          // strip file name with strip_prefix ("" : none written)
  std::string same_as;        // an earlier technique of the scene with the same image, bit for bit
};

struct FidelityScene {
  std::string name;   // built-in name, or a scene file as "scenes/spot.json"
  std::string label;  // short name for the page and file names ("columns", "spot")
  size_t triangles = 0;
  int lights = 0;
  double oracle_ms = 0;  // the oracle_rays reference, all lights, one run
  std::vector<RayErrorPoint> curve;  // the oracle's error per searched count (as far as needed)
  std::vector<FidelityRow> rows;
};

struct FidelityResult {
  std::vector<FidelityScene> scenes;
  std::vector<std::pair<std::string, std::string>> skipped;  // scene, why
  std::string cpu;
  int cores = 0;
  int threads = 0;
  std::string simd_target;
  std::string date;  // UTC, ISO 8601
  double seconds = 0;  // the whole run
  FidelityOptions options;  // as run (log dropped)
};

// Soft techniques that are not ray-traced, in registry order.
std::vector<std::string> fidelityTechniques();

// The default scene list: every built-in scene, then every .json scene file of each folder of
// `scene_dirs` (sorted per folder) whose "models:" files are all present; the others go to
// `skipped` with the missing models named.
std::vector<std::string> fidelityScenes(const std::vector<std::string>& scene_dirs,
                                        std::vector<std::pair<std::string, std::string>>& skipped);

// Runs the page's measurements. Throws penumbra::Error for bad options (size, ray counts, an
// unknown technique or scene) before measuring anything. A scene that fails to load is skipped
// with its error; a technique that refuses a scene gets a row with `failure`.
FidelityResult runFidelity(const FidelityOptions& options);

}  // namespace penumbra
