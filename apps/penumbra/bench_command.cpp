// penumbra bench: the 2004 paper's evaluation (section 7) as a sweep over scenes, wedge
// implementations, culling modes and tile sizes (evaluation/sweep.h), written as CSV, a
// markdown summary (evaluation/sweep_report.h) and plots: the library spawns no process, the
// command runs scripts/plot_sweep.py with Debian's /usr/bin/python3 itself.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "evaluation/sweep.h"
#include "evaluation/sweep_report.h"
#include "shadows/technique.h"

extern char** environ;

namespace penumbra::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

// The plotting script of the source tree this binary was built from.
std::string plotScriptPath() {
  return (std::filesystem::path(PENUMBRA_SOURCE_DIR) / "scripts" / "plot_sweep.py").string();
}

// The plot command as a user would type it, for messages.
std::string plotCommandLine(const std::string& csv, const std::string& out_dir) {
  return fmt::format("{} '{}' --csv '{}' --out '{}'", kPython, plotScriptPath(), csv, out_dir);
}

// Runs `args` (args[0] an absolute path, no shell) and waits for it. Its stdout, and its stderr
// when `quiet_stderr`, go to /dev/null when asked. Returns a description of the failure, empty
// when it exited with status 0.
std::string runProcess(const std::vector<std::string>& args, bool quiet_stdout,
                       bool quiet_stderr) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet_stdout)
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (quiet_stderr)
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return fmt::format("cannot start {}: {}", args[0], std::strerror(spawned));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return fmt::format("cannot wait for {}: {}", args[0], std::strerror(errno));
  }
  if (WIFEXITED(status))
    return WEXITSTATUS(status) == 0 ? std::string()
                                    : fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("killed by signal {}", WTERMSIG(status));
  return "stopped abnormally";
}

// Why the plots cannot be drawn here (empty: they can): no python3, no script, no matplotlib.
std::string plottingUnavailable() {
  if (!std::filesystem::exists(kPython))
    return fmt::format("no {} (apt-get install python3-matplotlib)", kPython);
  if (!std::filesystem::exists(plotScriptPath()))
    return fmt::format("no plotting script at {}", plotScriptPath());
  if (!runProcess({kPython, "-c", "import matplotlib"}, true, true).empty())
    return fmt::format("{} cannot import matplotlib (apt-get install python3-matplotlib)",
                       kPython);
  return {};
}

// Draws the plots of `csv` into `out_dir` with scripts/plot_sweep.py; on failure says why and
// how to plot later. Plotting is optional: it never changes the command's exit code.
void plotSweep(const std::string& csv, const std::string& out_dir, bool quiet) {
  const std::string command = plotCommandLine(csv, out_dir);
  const std::string unavailable = plottingUnavailable();
  if (!unavailable.empty()) {
    if (!quiet)
      std::cout << fmt::format("no plots: {}; plot later with:\n  {}\n", unavailable, command);
    return;
  }
  std::cout.flush();  // the summary before the script's own lines
  const std::string failure =
      runProcess({kPython, plotScriptPath(), "--csv", csv, "--out", out_dir}, quiet, false);
  if (!failure.empty())
    std::cerr << "penumbra: plotting failed (" << failure << "); run: " << command << std::endl;
}

struct BenchArgs {
  std::vector<std::string> scenes = SweepOptions{}.scenes;
  int width = SweepOptions{}.width;
  int height = SweepOptions{}.height;
  int repeat = SweepOptions{}.repeat;
  std::string out = "out/sweep";
  std::vector<int> tile_levels = SweepOptions{}.tile_levels;
  std::vector<std::string> techniques = {"wedge-3pass", "wedge-1pass"};
  std::vector<std::string> cull = {"none", "zmax", "full"};
  bool no_2002 = false;
  int oracle_rays = SweepOptions{}.oracle_rays;
  std::string oracle_scene = SweepOptions{}.oracle_scene;
  int oracle_repeat = SweepOptions{}.oracle_repeat;
  bool smooth = false;
  bool two_level = false;
  int threads = 0;
  bool scalar = false;
  bool no_plots = false;
  bool quiet = false;
};

int runBench(const BenchArgs& args) {
  SweepOptions options;
  options.scenes = args.scenes;
  options.width = args.width;
  options.height = args.height;
  options.repeat = args.repeat;
  options.tile_levels = args.tile_levels;
  options.implementations.clear();
  for (const std::string& name : args.techniques)
    options.implementations.push_back(findTechnique(name).name);
  options.cull_modes.clear();
  for (const std::string& name : args.cull) options.cull_modes.push_back(parseCullMode(name));
  options.original_2002 = !args.no_2002;
  options.oracle_rays = args.oracle_rays;
  options.oracle_scene = args.oracle_scene;
  options.oracle_repeat = args.oracle_repeat;
  options.smooth_falloff = args.smooth;
  options.two_level_stencil = args.two_level;
  options.threads = args.threads;
  options.simd = !args.scalar;
  options.show_progress = !args.quiet;
  // Mismatches are printed whether quiet or not: they mean a wrong image.
  options.log = [quiet = args.quiet](const std::string& line) {
    if (!quiet || line.rfind("MISMATCH", 0) == 0 || line.rfind("UNREPEATABLE", 0) == 0)
      std::cerr << line << std::endl;
  };

  const SweepResult result = runSweep(options);
  const std::filesystem::path out_dir = args.out;
  std::filesystem::create_directories(out_dir);
  const std::string csv = (out_dir / "sweep.csv").string();
  writeSweepCsv(csv, result);
  const std::string summary = sweepSummaryMarkdown(result);
  {
    std::ofstream md(out_dir / "summary.md");
    md << summary;
    PENUMBRA_CHECK(md.good(), "cannot write '{}'", (out_dir / "summary.md").string());
  }
  if (!args.quiet)
    std::cout << summary << fmt::format("\nwrote {}, {}\n", csv, (out_dir / "summary.md").string());

  if (!args.no_plots) plotSweep(csv, out_dir.string(), args.quiet);

  if (result.cullMismatches() > 0 || result.unrepeatableRows() > 0) {
    std::cerr << fmt::format(
        "penumbra: error: {} configuration(s) changed visibility with culling, {} gave "
        "different counters on repeated runs (see {}: cull_mismatch_pixels, "
        "counters_repeatable)\n",
        result.cullMismatches(), result.unrepeatableRows(), csv);
    return 1;
  }
  return 0;
}

}  // namespace

Subcommand addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Sweep the wedge implementations over culling modes and tile sizes (2004 paper, section 7): "
      "CSV, summary and plots");
  cmd->add_option("--scenes", args->scenes, "Scenes, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--width", args->width, "Image width")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  cmd->add_option("--repeat", args->repeat, "Timed runs per configuration (median reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("-o,--out", args->out, "Output folder: sweep.csv, summary.md, PNG plots")
      ->capture_default_str();
  cmd->add_option("--tile-levels", args->tile_levels,
                  "Culling tiles 2^n x 2^n, n comma separated in 1..8")
      ->delimiter(',')
      ->check(CLI::Range(1, 8))
      ->capture_default_str();
  cmd->add_option("--techniques", args->techniques, "Implementations: wedge-3pass, wedge-1pass")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--cull", args->cull, "Culling modes: none, zmax, full")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_flag("--no-2002", args->no_2002, "Skip the 2002 algorithm (Figure 10a's baseline)");
  cmd->add_option("--oracle-rays", args->oracle_rays, "Oracle rays per pixel (0: no oracle)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--oracle-scene", args->oracle_scene, "Scene the oracle runs on")
      ->capture_default_str();
  cmd->add_option("--oracle-repeat", args->oracle_repeat, "Timed oracle runs")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_flag("--smooth", args->smooth, "Smooth falloff s' = 3s^2 - 2s^3 in the wedges");
  cmd->add_flag("--two-level", args->two_level,
                "Umbra through the two-level stencil (Aila 2005), as `render` does; off: the "
                "2004 paper's passes");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--scalar", args->scalar, "Run the scalar twins of the SIMD kernels");
  cmd->add_flag("--no-plots", args->no_plots, "Write CSV and summary only");
  cmd->add_flag("-q,--quiet", args->quiet, "Print only errors and mismatches");
  return {cmd, [args] { return runBench(*args); }};
}

}  // namespace penumbra::cli
