// penumbra fidelity: every soft technique against the ray-traced oracle on every scene
// (evaluation/fidelity.h), written as docs/fidelity.md with image strips beside it
// (evaluation/fidelity_report.h) and a CSV of every number.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli_checks.h"
#include "commands.h"
#include "core/error.h"
#include "evaluation/fidelity.h"
#include "evaluation/fidelity_report.h"
#include "scene/builtin_scenes.h"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

struct FidelityArgs {
  std::string size = "320x214";
  std::vector<std::string> scenes;
  std::vector<std::string> techniques;
  int oracle_rays = 1024;
  int max_search_rays = 512;
  int runs = 3;
  std::string out = "out/fidelity";
  std::string doc = "docs/fidelity.md";
  int shrink = 2;
  int threads = 0;
  bool scalar = false;
  bool quiet = false;
};

void parseSize(const std::string& text, int& width, int& height) {
  char x = 0;
  char rest = 0;
  const int n = std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest);
  PENUMBRA_CHECK(n == 3 && (x == 'x' || x == 'X'), "--size '{}' is not WIDTHxHEIGHT (e.g. 320x214)",
                 text);
}

const fs::path kScenes = fs::path(PENUMBRA_SOURCE_DIR) / "scenes";
// Scene files made to show the approximations' failures (terrain under a low light, a large
// light); kept out of scenes/ itself, whose every file the oracle test suites render.
const fs::path kFailureModeScenes = kScenes / "failure-modes";
// Scene files whose models the repository cannot ship nor fetch (see models/README.md): on the
// page where a models folder holds them, skipped otherwise.
const fs::path kTestDataScenes = fs::path(PENUMBRA_SOURCE_DIR) / "tests" / "data" / "scenes";

// A scene named on the command line: a built-in name, a path, or the name of a scene file of
// the source tree ("spot" for scenes/spot.json, "large-light" for scenes/failure-modes/,
// "armadillo" for tests/data/scenes/armadillo.json).
std::string resolveScene(const std::string& name) {
  if (isBuiltinScene(name) || fs::exists(name)) return name;
  for (const fs::path& dir : {kScenes, kTestDataScenes, kFailureModeScenes}) {
    const fs::path file = dir / (name + ".json");
    if (fs::exists(file)) return file.string();
  }
  throw Error(fmt::format(
      "--scenes: '{}' is neither a built-in scene ({}), a file, nor a scene file of {}, {} or {}",
      name, fmt::join(builtinSceneNames(), ", "), kScenes.string(), kTestDataScenes.string(),
      kFailureModeScenes.string()));
}

// The command as a user would type it again: the options that differ from the defaults.
std::string commandLine(const FidelityArgs& a) {
  const FidelityArgs d;
  std::string line = "penumbra fidelity";
  if (a.size != d.size) line += " --size " + a.size;
  if (!a.scenes.empty()) line += fmt::format(" --scenes {}", fmt::join(a.scenes, ","));
  if (!a.techniques.empty()) line += fmt::format(" --techniques {}", fmt::join(a.techniques, ","));
  if (a.oracle_rays != d.oracle_rays) line += fmt::format(" --oracle-rays {}", a.oracle_rays);
  if (a.max_search_rays != d.max_search_rays)
    line += fmt::format(" --max-search-rays {}", a.max_search_rays);
  if (a.runs != d.runs) line += fmt::format(" --runs {}", a.runs);
  if (a.shrink != d.shrink) line += fmt::format(" --shrink {}", a.shrink);
  if (a.threads != d.threads) line += fmt::format(" --threads {}", a.threads);
  if (a.scalar) line += " --scalar";
  if (a.out != d.out) line += " --out " + a.out;
  if (a.doc != d.doc) line += " --doc " + a.doc;
  return line;
}

int runFidelityCommand(const FidelityArgs& args) {
  FidelityOptions o;
  parseSize(args.size, o.width, o.height);
  std::vector<std::pair<std::string, std::string>> skipped;
  if (args.scenes.empty()) {
    o.scenes = fidelityScenes(
        {kScenes.string(), kTestDataScenes.string(), kFailureModeScenes.string()}, skipped);
  } else {
    for (const std::string& s : args.scenes) o.scenes.push_back(resolveScene(s));
  }
  o.techniques = args.techniques;
  o.oracle_rays = args.oracle_rays;
  o.max_search_rays = args.max_search_rays;
  o.timing_runs = args.runs;
  o.strip_shrink = args.shrink;
  o.threads = args.threads;
  o.simd = !args.scalar;
  o.show_progress = !args.quiet && isatty(STDERR_FILENO);
  PENUMBRA_CHECK(!args.doc.empty() && fs::path(args.doc).extension() == ".md",
                 "--doc '{}' must be a .md file", args.doc);
  // The strips live beside the page, linked relatively; the folder is the page's own: PNGs of
  // an earlier run are removed so none stays that the page no longer shows.
  const fs::path strip_dir = fs::path(args.doc).parent_path() / "images" / "fidelity";
  o.strip_dir = strip_dir.string();
  o.strip_prefix = "images/fidelity/";
  o.log = [&](const std::string& line) {
    if (!args.quiet) std::cout << line << std::endl;
  };
  for (const auto& [scene, why] : skipped) o.log(fmt::format("skipping {}: {}", scene, why));

  std::error_code ec;
  if (fs::is_directory(strip_dir, ec))
    for (const auto& entry : fs::directory_iterator(strip_dir))
      if (entry.path().extension() == ".png") fs::remove(entry.path());
  FidelityResult result = runFidelity(o);
  result.skipped.insert(result.skipped.begin(), skipped.begin(), skipped.end());

  fs::create_directories(args.out);
  const fs::path csv = fs::path(args.out) / "fidelity.csv";
  std::ofstream(csv) << fidelityCsv(result);
  if (!fs::path(args.doc).parent_path().empty()) fs::create_directories(fs::path(args.doc).parent_path());
  std::ofstream doc(args.doc);
  doc << fidelityMarkdown(result, commandLine(args));
  PENUMBRA_CHECK(doc.good(), "cannot write '{}'", args.doc);
  if (!args.quiet)
    std::cout << fmt::format("wrote {}, {} and the strips in {} ({} scenes, {:.0f} s)\n",
                             args.doc, csv.string(), strip_dir.string(), result.scenes.size(),
                             result.seconds);
  return 0;
}

}  // namespace

Subcommand addFidelityCommand(CLI::App& app) {
  auto args = std::make_shared<FidelityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fidelity",
      "Every soft technique against the ray-traced oracle on every scene: errors, equal-error "
      "ray counts, times, image strips (docs/fidelity.md)");
  cmd->add_option("--size", args->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--scenes", args->scenes,
                  "Scenes, comma separated: built-in names, scene files, or names of "
                  "scenes/*.json (default: every built-in scene and every scene file whose "
                  "models are present)")
      ->delimiter(',');
  cmd->add_option("--techniques", args->techniques,
                  "Techniques, comma separated (default: every soft one that is not ray-traced)")
      ->delimiter(',');
  cmd->add_option("--oracle-rays", args->oracle_rays, "Rays per pixel of the reference")
      ->check(wholeNumberIn(1, 4096))
      ->capture_default_str();
  cmd->add_option("--max-search-rays", args->max_search_rays,
                  "Largest oracle ray count of the equal-error search (a power of two below "
                  "--oracle-rays)")
      ->check(wholeNumberIn(1, 2048))
      ->capture_default_str();
  cmd->add_option("--runs", args->runs, "Timed renders per technique (median reported)")
      ->check(wholeNumberIn(1, 100))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Folder of fidelity.csv")->capture_default_str();
  cmd->add_option("--doc", args->doc,
                  "The page to write; its strips go to images/fidelity/ beside it")
      ->capture_default_str();
  cmd->add_option("--shrink", args->shrink, "Strips shrunk by 1, 2 or 4")
      ->check(wholeNumberIn(1, 4))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(wholeNumberIn(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--scalar", args->scalar, "Run the scalar twins of the SIMD kernels");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing, draw no progress bar");
  return {cmd, [args] { return runFidelityCommand(*args); }};
}

}  // namespace penumbra::cli
