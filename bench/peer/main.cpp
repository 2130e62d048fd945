// penumbra_llvmpipe_peer: the benchmark peer of our hard-shadow frame. Mesa's llvmpipe (a
// multithreaded software rasterizer) renders the same scene, size and light with classic z-fail
// stencil shadow volumes; run it next to `penumbra bench` on the same machine and quote ratios.
//
//   penumbra_llvmpipe_peer --scene spheres --width 640 --height 427 --frames 30 --warmup 5
//                          --threads 2 [--png out.png] [--json results.json]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image_io.h"
#include "core/parallel.h"
#include "headless_gl.h"
#include "peer_renderer.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"

namespace penumbra {
namespace {

struct Arguments {
  std::string scene = "spheres";
  int width = 640;
  int height = 427;
  int frames = 30;
  int warmup = 5;
  int threads = 2;
  CasterMode casters = CasterMode::kOneSided;
  DepthFormat depth = DepthFormat::kDepth24Stencil8;
  bool breakdown = false;
  std::string png;
  std::string json;
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

const char* casterName(CasterMode mode) {
  return mode == CasterMode::kOneSided ? "one-sided" : "two-sided";
}
const char* depthName(DepthFormat format) {
  return format == DepthFormat::kDepth24Stencil8 ? "d24s8" : "d32fs8";
}

int run(const Arguments& args) {
  PENUMBRA_CHECK(args.frames >= 1 && args.warmup >= 0, "--frames must be >= 1, --warmup >= 0");
  // TBB workers for findSilhouette's parallel loop: the same budget llvmpipe gets.
  ThreadLimit thread_limit(args.threads);
  HeadlessGl gl(args.threads);
  const Scene scene = loadScene(args.scene);
  PeerOptions options;
  options.width = args.width;
  options.height = args.height;
  options.casters = args.casters;
  options.depth = args.depth;
  options.pass_breakdown = args.breakdown;
  PeerRenderer renderer(scene, options);
  const MachineInfo machine = machineInfo();

  std::printf("llvmpipe peer: scene %s %dx%d, %zu triangles (%zu merged vertices), %zu lights\n",
              scene.name.c_str(), args.width, args.height, renderer.sceneTriangles(),
              renderer.sceneVertices(), scene.lights.size());
  std::printf("  GL_RENDERER  %s\n  GL_VERSION   %s\n", gl.renderer().c_str(),
              gl.version().c_str());
  std::printf("  CPU          %s (%d hardware threads), LP_NUM_THREADS=%d\n",
              machine.cpu_model.c_str(), machine.cores, args.threads);
  std::printf("  z-fail volumes, %s casters, %s depth-stencil, RGBA8 colour\n",
              casterName(args.casters), depthName(args.depth));

  for (int i = 0; i < args.warmup; ++i) renderer.renderFrame();
  std::vector<double> frame_ms, eye_ms, volumes_ms, shading_ms;
  PeerFrameStats last;
  for (int i = 0; i < args.frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    last = renderer.renderFrame();
    frame_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    eye_ms.push_back(last.eye_ms);
    volumes_ms.push_back(last.volumes_ms);
    shading_ms.push_back(last.shading_ms);
  }
  const double median_ms = median(frame_ms);
  const double min_ms = *std::min_element(frame_ms.begin(), frame_ms.end());
  const double max_ms = *std::max_element(frame_ms.begin(), frame_ms.end());

  std::printf("  volumes      %llu silhouette edges, %llu side quads, %llu cap triangles, "
              "%llu volume triangles per frame\n",
              (unsigned long long)last.silhouette_edges, (unsigned long long)last.side_quads,
              (unsigned long long)last.cap_triangles, (unsigned long long)last.volume_triangles);
  if (args.breakdown) {
    std::printf("  passes       eye %.3f ms, volumes %.3f ms, shading %.3f ms (medians, with a "
                "glFinish after each)\n",
                median(eye_ms), median(volumes_ms), median(shading_ms));
  }
  std::printf("  frame        median %.3f ms (%.1f fps), min %.3f ms, max %.3f ms over %d frames "
              "after %d warm-up\n",
              median_ms, 1000.0 / median_ms, min_ms, max_ms, args.frames, args.warmup);

  if (!args.png.empty()) {
    writePng(args.png, renderer.readColor());
    std::printf("  wrote %s\n", args.png.c_str());
  }
  if (!args.json.empty()) {
    nlohmann::json j;
    j["peer"] = "llvmpipe z-fail stencil shadow volumes";
    j["scene"] = scene.name;
    j["width"] = args.width;
    j["height"] = args.height;
    j["triangles"] = renderer.sceneTriangles();
    j["lights"] = scene.lights.size();
    j["casters"] = casterName(args.casters);
    j["depth_format"] = depthName(args.depth);
    j["color_format"] = "rgba8";
    j["gl_renderer"] = gl.renderer();
    j["gl_version"] = gl.version();
    j["cpu_model"] = machine.cpu_model;
    j["cores"] = machine.cores;
    j["lp_num_threads"] = args.threads;
    j["warmup"] = args.warmup;
    j["frames"] = args.frames;
    j["frame_ms"] = frame_ms;
    j["median_ms"] = median_ms;
    j["min_ms"] = min_ms;
    j["max_ms"] = max_ms;
    j["fps_median"] = 1000.0 / median_ms;
    j["silhouette_edges"] = last.silhouette_edges;
    j["side_quads"] = last.side_quads;
    j["cap_triangles"] = last.cap_triangles;
    j["volume_triangles"] = last.volume_triangles;
    j["pass_breakdown"] = args.breakdown;
    if (args.breakdown) {
      j["eye_ms_median"] = median(eye_ms);
      j["volumes_ms_median"] = median(volumes_ms);
      j["shading_ms_median"] = median(shading_ms);
    }
    createParentDirectories(args.json);
    std::ofstream file(args.json);
    file << j.dump(2) << "\n";
    PENUMBRA_CHECK(file.good(), "llvmpipe peer: cannot write '{}'", args.json);
    std::printf("  wrote %s\n", args.json.c_str());
  }
  return 0;
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  using penumbra::CasterMode;
  using penumbra::DepthFormat;
  penumbra::Arguments args;
  CLI::App app{"Mesa llvmpipe z-fail stencil shadow volumes: the peer of our hard-shadow frame"};
  app.add_option("--scene", args.scene, "Built-in scene name, scene .json or mesh file")
      ->capture_default_str();
  app.add_option("--width", args.width, "Image width")->capture_default_str()->check(
      CLI::Range(1, 8192));
  app.add_option("--height", args.height, "Image height")->capture_default_str()->check(
      CLI::Range(1, 8192));
  app.add_option("--frames", args.frames, "Timed frames")->capture_default_str()->check(
      CLI::PositiveNumber);
  app.add_option("--warmup", args.warmup, "Untimed frames first")->capture_default_str()->check(
      CLI::NonNegativeNumber);
  app.add_option("--threads", args.threads,
                 "llvmpipe rasterizer threads (LP_NUM_THREADS) and silhouette workers")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  std::string casters = "one-sided", depth = "d24s8";
  app.add_option("--casters", casters,
                 "one-sided: classic Everitt-Kilgard volumes of light-facing triangles for closed "
                 "meshes; two-sided: our renderer's volumes (every triangle casts)")
      ->capture_default_str()
      ->check(CLI::IsMember({"one-sided", "two-sided"}));
  app.add_option("--depth", depth, "Depth-stencil format")
      ->capture_default_str()
      ->check(CLI::IsMember({"d24s8", "d32fs8"}));
  app.add_flag("--breakdown", args.breakdown,
               "Also time the passes apart (a glFinish after each; slows the frame)");
  app.add_option("--png", args.png, "Write the last frame (sRGB PNG)");
  app.add_option("--json", args.json, "Write the timings and counters as JSON");
  CLI11_PARSE(app, argc, argv);
  args.casters = casters == "one-sided" ? CasterMode::kOneSided : CasterMode::kTwoSided;
  args.depth = depth == "d24s8" ? DepthFormat::kDepth24Stencil8 : DepthFormat::kDepth32FStencil8;
  try {
    return penumbra::run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penumbra_llvmpipe_peer: %s\n", e.what());
    return 1;
  }
}
