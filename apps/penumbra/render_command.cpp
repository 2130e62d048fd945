// penumbra render SCENE: one frame, written as PNG (and optionally visibility, depth, stats).
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "core/error.h"
#include "render/frame.h"
#include "render/image_io.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"
#include "shadows/technique.h"

namespace penumbra::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string output;
  std::string technique = "wedge-3pass";  // soft shadows; radius-0 lights give hard ones
  int rays = TechniqueOptions{}.rays;
  bool hard = false;
  std::string volume_mode = "auto";
  std::string cull = cullModeName(TechniqueOptions{}.cull);
  int tile_size = 1 << TechniqueOptions{}.tile_level;
  bool smooth = false;
  bool one_level_stencil = false;
  int width = 0;
  int height = 0;
  int threads = 0;
  bool scalar = false;
  uint64_t seed = TechniqueOptions{}.seed;
  std::string visibility_exr;
  std::string visibility_png;
  std::string depth_exr;
  std::string stats_json;
  bool quiet = false;
};

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

// Culling tiles are 2^n x 2^n pixels, n = 1..8 (TechniqueOptions::tile_level).
int tileLevel(int tile_size) {
  for (int level = 1; level <= 8; ++level)
    if (tile_size == 1 << level) return level;
  throw Error(fmt::format("--tile-size {} is not a power of two in 2..256", tile_size));
}

int runRender(const RenderArgs& args) {
  FrameOptions options;
  options.technique.kind = parseTechniqueName(args.technique);
  options.technique.volume_mode = parseVolumeMode(args.volume_mode);
  options.technique.cull = parseCullMode(args.cull);
  options.technique.tile_level = tileLevel(args.tile_size);
  options.technique.smooth_falloff = args.smooth;
  options.technique.two_level_stencil = !args.one_level_stencil;
  options.technique.rays = args.rays;
  options.technique.hard = args.hard;
  options.technique.seed = args.seed;
  options.technique.simd = !args.scalar;
  options.technique.show_progress = !args.quiet;
  options.width = args.width;
  options.height = args.height;
  options.threads = args.threads;
  requireExtension(args.output, ".png", "output");
  requireExtension(args.visibility_exr, ".exr", "--visibility");
  requireExtension(args.visibility_png, ".png", "--visibility-png");
  requireExtension(args.depth_exr, ".exr", "--depth");
  requireExtension(args.stats_json, ".json", "--stats");

  const Scene scene = loadScene(args.scene);
  const FrameResult result = renderFrame(scene, options);

  std::vector<std::string> written;
  const std::string output = args.output.empty() ? defaultOutput(scene.name) : args.output;
  writePng(output, result.color);
  written.push_back(output);
  for (size_t i = 0; i < result.lights.size(); ++i) {
    if (!args.visibility_exr.empty()) {
      written.push_back(indexedOutputPath(args.visibility_exr, i));
      writeExr(written.back(), result.lights[i].visibility);
    }
    if (!args.visibility_png.empty()) {
      written.push_back(indexedOutputPath(args.visibility_png, i));
      writePngGray(written.back(), result.lights[i].visibility);
    }
  }
  if (!args.depth_exr.empty()) {
    writeExr(args.depth_exr, result.eye.depth.depth);
    written.push_back(args.depth_exr);
  }
  if (!args.stats_json.empty()) {
    writeStatsJson(args.stats_json, scene, options, result);
    written.push_back(args.stats_json);
  }

  if (!args.quiet) {
    std::cout << frameSummaryLine(scene, options, result) << "\n";
    std::cout << fmt::format("wrote {}\n", fmt::join(written, ", "));
  }
  return 0;
}

}  // namespace

Subcommand addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render one frame of a scene");
  cmd->add_option("scene", args->scene,
                  "Built-in scene name (see 'penumbra scenes'), scene .json file or mesh file")
      ->required();
  cmd->add_option("-o,--output", args->output, "Output PNG (default: out/<scene>.png)");
  cmd->add_option("--technique", args->technique,
                  fmt::format("Shadow technique: {}", fmt::join(techniqueNames(), ", ")))
      ->capture_default_str();
  cmd->add_option("--rays", args->rays, "Oracle rays per pixel over the light")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  cmd->add_flag("--hard", args->hard, "Hard shadows from the light centre");
  cmd->add_option("--volume-mode", args->volume_mode, "Shadow volumes: auto, zpass or zfail")
      ->capture_default_str();
  cmd->add_option("--cull", args->cull,
                  "Wedge tile culling: none, zmax (z-max only) or full (z-min and z-max)")
      ->capture_default_str();
  cmd->add_option("--tile-size", args->tile_size,
                  "Wedge culling tile size in pixels, a power of two in 2..256")
      ->capture_default_str();
  cmd->add_flag("--smooth", args->smooth, "Wedges: smooth falloff s' = 3s^2 - 2s^3");
  cmd->add_flag("--one-level-stencil", args->one_level_stencil,
                "Umbra pixel by pixel, as the papers' passes (default: tiles a volume polygon "
                "covers and passes whole take one coarse stencil write)");
  cmd->add_option("--width", args->width, "Image width (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--scalar", args->scalar, "Run the scalar twins of the SIMD kernels");
  cmd->add_option("--seed", args->seed, "Random seed of the oracle's ray directions")
      ->capture_default_str();
  cmd->add_option("--visibility", args->visibility_exr,
                  "Visibility EXR of light 0 (light i > 0: name.i.exr)");
  cmd->add_option("--visibility-png", args->visibility_png,
                  "Visibility as gray PNG of light 0 (light i > 0: name.i.png)");
  cmd->add_option("--depth", args->depth_exr, "Eye depth EXR (reversed-Z, 0 = background)");
  cmd->add_option("--stats", args->stats_json, "Stats JSON: counters and times per pass");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing, draw no progress bar");
  return {cmd, [args] { return runRender(*args); }};
}

}  // namespace penumbra::cli
