// penumbra render SCENE: one frame, written as PNG (and optionally visibility, depth, stats).
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_checks.h"
#include "commands.h"
#include "core/error.h"
#include "core/image_io.h"
#include "render/frame.h"
#include "render/frame_timing.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_report.h"
#include "shadows/technique.h"
#include "path_frames.h"
#include "technique_flags.h"

namespace penumbra::cli {
namespace {

// A technique option on the command line: one CLI11 option per distinct name over all
// registered techniques, applied to the chosen technique only when given.
struct TechniqueFlag {
  std::string name;
  OptionKind kind = OptionKind::Flag;
  CLI::Option* option = nullptr;
  std::string value;  // Integer and Choice options
  bool given = false;  // Flag options
};

struct RenderArgs {
  CLI::App* command = nullptr;  // to tell an option given empty ("-o ''") from one not given
  std::string scene;
  std::string output;
  std::string technique = kDefaultTechnique;  // soft shadows; radius-0 lights give hard ones
  std::vector<std::unique_ptr<TechniqueFlag>> technique_flags;
  int width = 0;
  int height = 0;
  int threads = 0;
  int frames = 0;  // 0: one cold frame; N: N warm frames timed after `warmup` untimed ones
  // The first frames fault in the memory their passes allocate on each worker thread (on
  // dragon-res2 `exact`, frames 2 and 3 still faulted some 2,000 pages each and took 25 % longer
  // than the fourth): three untimed frames reach the steady state, as the llvmpipe peer's do.
  int warmup = 3;
  bool scalar = false;
  long long delay_stream = 0;      // bytes of the eye pass's delay stream; 0: none
  bool depth_complexity = false;  // count the eye pass's depth passes and covered pixels
  std::string caster_culling = "auto";
  std::string occlusion_culling = "auto";
  std::string visibility_exr;
  std::string visibility_png;
  std::string depth_exr;
  std::string stats_json;
  bool quiet = false;
  std::string up = "y";
  bool path = false;         // every frame of the scene's camera and light path
  int frame = -1;            // one frame of it
  bool list_frames = false;  // print the path's frame numbers (for GNU parallel, Slurm arrays)
};

// One line per mesh read from a file, before the frame; warnings go to stderr even with
// --quiet, because a mesh that did not load as its file says is never to pass silently.
void printMeshReports(const Scene& scene, bool quiet) {
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    for (const std::string& warning : mesh.file_counts.warnings) {
      std::cerr << "penumbra: warning: " << warning << "\n";
    }
    if (!quiet && mesh.file_counts.vertices > 0) {
      std::cout << "mesh " << meshReportLine(reportMesh(mesh, scene.adjacency[i])) << "\n";
    }
  }
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Checked before rendering so a typo costs nothing.
void requireExtension(const std::string& path, const char* ext, const char* what) {
  if (path.empty()) return;
  PENUMBRA_CHECK(lowerExtension(path) == ext, "{} '{}' must be a {} file", what, path, ext);
}

// out/<scene>.png, with the scene name reduced to characters safe in a file name.
std::string defaultOutput(const std::string& scene_name) {
  std::string name = std::filesystem::path(scene_name).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return "out/" + (name.empty() ? std::string("scene") : name) + ".png";
}

// Renders the scene's current view and writes the outputs; `frame` >= 0 numbers every output
// file as frame `frame` of the scene's path (path_frames.h).
int renderView(const RenderArgs& args, const FrameOptions& options, const Scene& scene, int frame) {
  const auto named = [&](const std::string& path) {
    return frame < 0 || path.empty() ? path : frameOutputPath(path, frame, scene.path.frames);
  };
  const std::string output = named(args.output.empty() ? defaultOutput(scene.name) : args.output);
  const std::string visibility_exr = named(args.visibility_exr);
  const std::string visibility_png = named(args.visibility_png);
  const std::string depth_exr = named(args.depth_exr);
  const std::string stats_json = named(args.stats_json);
  std::vector<NamedOutput> outputs = {{"-o", output}};
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (!visibility_exr.empty()) {
      outputs.push_back({"--visibility", indexedOutputPath(visibility_exr, i)});
    }
    if (!visibility_png.empty()) {
      outputs.push_back({"--visibility-png", indexedOutputPath(visibility_png, i)});
    }
  }
  if (!depth_exr.empty()) outputs.push_back({"--depth", depth_exr});
  if (!stats_json.empty()) outputs.push_back({"--stats", stats_json});
  checkDistinctOutputs(outputs);

  FrameResult result;
  std::string timings;
  if (args.frames > 0) {
    // The technique is prepared once; the outputs are the last frame's.
    const FrameRenderer renderer(scene, options);
    timings = frameTimingsLine(timeFrames(renderer, args.frames, args.warmup, result));
  } else {
    result = renderFrame(scene, options);
  }

  std::vector<std::string> written;
  writePng(output, result.color);
  written.push_back(output);
  for (size_t i = 0; i < result.lights.size(); ++i) {
    if (!visibility_exr.empty()) {
      written.push_back(indexedOutputPath(visibility_exr, i));
      writeExr(written.back(), result.lights[i].visibility);
    }
    if (!visibility_png.empty()) {
      written.push_back(indexedOutputPath(visibility_png, i));
      writePngGray(written.back(), result.lights[i].visibility);
    }
  }
  if (!depth_exr.empty()) {
    writeExr(depth_exr, result.eye.depth.depth);
    written.push_back(depth_exr);
  }
  if (!stats_json.empty()) {
    writeStatsJson(stats_json, scene, options, result);
    written.push_back(stats_json);
  }

  if (!args.quiet) {
    std::cout << frameSummaryLine(scene, options, result) << "\n";
    if (!timings.empty()) std::cout << timings << "\n";
    std::cout << fmt::format("wrote {}\n", fmt::join(written, ", "));
  }
  return 0;
}

int runRender(const RenderArgs& args) {
  FrameOptions options;
  options.technique = TechniqueConfig(args.technique);
  // Only what was given: an option the chosen technique does not have is an error
  // (TechniqueConfig::set names the technique's own options), never silently ignored.
  for (const auto& flag : args.technique_flags) {
    if (flag->option->count() == 0) continue;
    options.technique.set(flag->name, flag->kind == OptionKind::Flag ? "true" : flag->value);
  }
  options.technique.validate();
  options.context.simd = !args.scalar;
  options.context.caster_culling = parseCasterCulling(args.caster_culling);
  options.context.show_progress = !args.quiet;
  options.context.threads = args.threads;
  options.delay_stream_bytes = size_t(args.delay_stream);
  options.depth_complexity = args.depth_complexity;
  options.occlusion_culling = parseOcclusionCulling(args.occlusion_culling);
  options.width = args.width;
  options.height = args.height;
  requireExtension(args.output, ".png", "output");
  requireExtension(args.visibility_exr, ".exr", "--visibility");
  requireExtension(args.visibility_png, ".png", "--visibility-png");
  requireExtension(args.depth_exr, ".exr", "--depth");
  requireExtension(args.stats_json, ".json", "--stats");

  // An output given as '' is a mistake, not a request for the default or for no file.
  for (const char* flag : {"--output", "--visibility", "--visibility-png", "--depth", "--stats"}) {
    const CLI::Option* option = args.command->get_option(flag);
    PENUMBRA_CHECK(option->count() == 0 || !option->as<std::string>().empty(),
                   "{} is given an empty file name", flag);
  }
  // --rays with --hard would be ignored: the oracle casts one ray per pixel.
  if (args.command->count("--rays") > 0 && options.technique.info().options.find("hard") &&
      options.technique.get("hard") == "true") {
    throw Error("--rays has no effect with --hard (one ray per pixel to the light centre)");
  }

  PENUMBRA_CHECK(!(args.path && args.frame >= 0),
                 "--path renders every frame of the path and --frame K one of them: give one");
  PENUMBRA_CHECK(!(args.list_frames && (args.path || args.frame >= 0)),
                 "--list-frames renders nothing: give it without --path and --frame");
  Scene scene = loadScene(args.scene, parseUpAxis(args.up));
  const std::vector<int> frames = framesToRender(scene, args.path || args.list_frames, args.frame);
  if (args.list_frames) {
    // One frame number a line: `penumbra render S --list-frames | parallel penumbra render S
    // --frame {}` (scripts/render-path-parallel.sh), or the size of a Slurm array.
    for (const int k : frames) std::cout << k << "\n";
    return 0;
  }
  PENUMBRA_CHECK(args.frames == 0 || frames.size() <= 1,
                 "--frames times one view; give --frame K instead of --path to time a frame of "
                 "the path");
  printMeshReports(scene, args.quiet);
  if (args.command->count("--rays") > 0) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
      if (scene.lights[i].radius > 0.0f) continue;
      std::cerr << fmt::format("penumbra: warning: --rays is unused for light {}: its radius is "
                               "0, so the oracle casts one ray per pixel\n",
                               i);
    }
  }
  if (frames.empty()) return renderView(args, options, scene, -1);
  for (const int k : frames) {
    applyPathFrame(scene, k);
    renderView(args, options, scene, k);
  }
  return 0;
}

}  // namespace

Subcommand addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render one frame of a scene");
  args->command = cmd;
  cmd->add_option("scene", args->scene,
                  "Built-in scene name (see 'penumbra scenes'), scene .json file or mesh file")
      ->required();
  cmd->add_option("-o,--output", args->output, "Output PNG (default: out/<scene>.png)");
  cmd->add_option("--technique", args->technique,
                  fmt::format("Shadow technique: {} ('penumbra techniques NAME' lists its "
                              "options)",
                              fmt::join(techniqueNames(), ", ")))
      ->capture_default_str();
  for (const TechniqueOptionUse& use : techniqueOptionUses()) {
    auto flag = std::make_unique<TechniqueFlag>();
    flag->name = use.spec->name;
    flag->kind = use.spec->kind;
    const std::string help =
        fmt::format("{} [{}]", use.spec->help, fmt::join(use.techniques, ", "));
    if (use.spec->kind == OptionKind::Flag) {
      flag->option = cmd->add_flag("--" + use.spec->name, flag->given, help);
    } else {
      flag->option = cmd->add_option("--" + use.spec->name, flag->value, help);
      flag->option->type_name(use.spec->kind == OptionKind::Integer  ? "INT"
                              : use.spec->kind == OptionKind::Number ? "NUMBER"
                                  : fmt::format("{}", fmt::join(use.spec->choices, "|")));
    }
    flag->option->group("Technique options");
    args->technique_flags.push_back(std::move(flag));
  }
  cmd->add_option("--width", args->width, "Image width (default: the scene's)")
      ->check(wholeNumberIn(1, 8192));
  cmd->add_option("--height", args->height, "Image height (default: the scene's)")
      ->check(wholeNumberIn(1, 8192));
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(wholeNumberIn(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--scalar", args->scalar, "Run the scalar twins of the SIMD kernels");
  cmd->add_option("--delay-stream", args->delay_stream,
                  "Ring buffer bytes of the eye pass's delay stream (delayed occlusion culling; "
                  "0: none). The image is the same; fewer eye-pass pixels are rasterized")
      ->check(wholeNumberIn(0, 1LL << 34))
      ->capture_default_str();
  cmd->add_flag("--depth-complexity", args->depth_complexity,
                "Count the eye pass's depth passes and covered pixels (eye_depth_passes, "
                "eye_covered_pixels in --stats)");
  cmd->add_option("--caster-culling", args->caster_culling,
                  "Leave out of the shadow volumes, wedges and potential edges the casters "
                  "whose shadow reaches no visible point (same image; docs/caster-culling.md); "
                  "auto: where the scene has at least as many edges as the frame has pixels")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  cmd->add_option("--occlusion-culling", args->occlusion_culling,
                  "Skip objects the eye pass can prove hidden (docs/occlusion-culling.md); the "
                  "image is the same either way. auto: where the scene has at least half as "
                  "many triangles as the frame has pixels")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  cmd->add_option("--frames", args->frames,
                  "Time N warm frames (technique prepared once) and print min / median / max "
                  "and each pass's median; outputs are the last frame's")
      ->check(wholeNumberIn(1, 100000));
  cmd->add_option("--warmup", args->warmup,
                  "Untimed frames before --frames (the first frames fault in their memory)")
      ->check(wholeNumberIn(0, 1000))
      ->capture_default_str();
  cmd->add_option("--visibility", args->visibility_exr,
                  "Visibility EXR of light 0 (light i > 0: name.i.exr)");
  cmd->add_option("--visibility-png", args->visibility_png,
                  "Visibility as gray PNG of light 0 (light i > 0: name.i.png)");
  cmd->add_option("--depth", args->depth_exr, "Eye depth EXR (reversed-Z, 0 = background)");
  cmd->add_option("--stats", args->stats_json, "Stats JSON: counters and times per pass");
  cmd->add_option("--up", args->up, "Up axis of a mesh file given as the scene (x, y or z)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  cmd->add_flag("--path", args->path,
                 "Render every frame of the scene's camera and light path, each output numbered "
                 "(out/city.png: out/city.0000.png, ...)")
      ->group("Paths");
  cmd->add_option("--frame", args->frame, "Render frame K of the scene's path (numbered as --path)")
      ->check(wholeNumberIn(0, 999999))
      ->group("Paths");
  cmd->add_flag("--list-frames", args->list_frames,
                "Print the path's frame numbers, one a line, and render nothing (a job list for "
                "GNU parallel or a Slurm array)")
      ->group("Paths");
  cmd->add_flag("-q,--quiet", args->quiet,
                "Print nothing but warnings, draw no progress bar");
  return {cmd, [args] { return runRender(*args); }};
}

}  // namespace penumbra::cli
