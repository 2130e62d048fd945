#include "evaluation/fidelity.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/simd_dispatch.h"
#include "evaluation/fidelity_strip.h"
#include "metrics/image_compare.h"
#include "raster/eye_pass.h"
#include "render/frame_timing.h"
#include "render/stats_json.h"
#include "scene/builtin_scenes.h"
#include "scene/model_sources.h"
#include "scene/scene_file.h"
#include "shadows/reference_options.h"
#include "shadows/technique.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

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

std::string sceneLabel(const std::string& name) {
  return isBuiltinScene(name) ? name : fs::path(name).stem().string();
}

// Scene files as the source tree names them ("scenes/spot.json"), not by absolute path: the
// path from its last "scenes" folder on, else the file name.
std::string displayName(const std::string& name) {
  if (isBuiltinScene(name)) return name;
  fs::path shown;
  for (const fs::path& part : fs::path(name)) {
    if (part == "scenes") shown.clear();
    shown /= part;
  }
  return shown.begin() != shown.end() && *shown.begin() == "scenes"
             ? shown.string()
             : fs::path(name).filename().string();
}

void checkOptions(const FidelityOptions& o) {
  PENUMBRA_CHECK(!o.scenes.empty(), "fidelity: no scenes given");
  PENUMBRA_CHECK(o.width >= 8 && o.height >= 8 && o.width <= 8192 && o.height <= 8192,
                 "fidelity: image size {}x{} is outside 8x8..8192x8192", o.width, o.height);
  PENUMBRA_CHECK(o.oracle_rays >= 1 && o.oracle_rays <= 4096,
                 "fidelity: oracle rays {} outside 1..4096", o.oracle_rays);
  equalErrorRayCounts(o.max_search_rays);  // throws for a count that is not a power of two
  PENUMBRA_CHECK(o.max_search_rays < o.oracle_rays,
                 "fidelity: the equal-error search's largest count {} must stay below the "
                 "reference's {} rays",
                 o.max_search_rays, o.oracle_rays);
  PENUMBRA_CHECK(o.timing_runs >= 1 && o.timing_runs <= 100,
                 "fidelity: timing runs {} outside 1..100", o.timing_runs);
  PENUMBRA_CHECK(o.tolerance >= 0.0 && o.tolerance < 1.0, "fidelity: tolerance {} outside [0, 1)",
                 o.tolerance);
  PENUMBRA_CHECK(o.strip_shrink == 1 || o.strip_shrink == 2 || o.strip_shrink == 4,
                 "fidelity: strip shrink {} is not 1, 2 or 4", o.strip_shrink);
  PENUMBRA_CHECK(o.heat_scale > 0.0f && o.heat_scale <= 1.0f,
                 "fidelity: heat map scale {} outside (0, 1]", o.heat_scale);
  for (const std::string& name : o.scenes)
    PENUMBRA_CHECK(isBuiltinScene(name) || fs::exists(name),
                   "fidelity: unknown scene '{}' (a built-in name or a scene file)", name);
  for (const std::string& name : o.techniques) {
    const TechniqueInfo& info = findTechnique(name);  // throws naming the known ones
    PENUMBRA_CHECK(info.traits.soft && !info.traits.ray_traced,
                   "fidelity: '{}' is not a soft technique measured against the oracle (soft, "
                   "not ray-traced: {})",
                   name, fmt::join(fidelityTechniques(), ", "));
  }
}

// Every light of the scene once with a prepared technique; the wall-clock time of the renders
// alone (preparation, such as the oracle's BVH, is not in it).
std::vector<Image<float>> renderLights(const PreparedTechnique& prepared, const Scene& scene,
                                       const View& view, const EyeBuffers& eye,
                                       const RenderContext& context, double& ms) {
  std::vector<Image<float>> out;
  const auto start = std::chrono::steady_clock::now();
  for (const Light& light : scene.lights)
    out.push_back(prepared.render(light, view, eye, context).visibility);
  ms = 1e3 * secondsSince(start);
  return out;
}

std::unique_ptr<PreparedTechnique> prepareOracle(const Scene& scene, int rays, uint64_t seed) {
  TechniqueConfig config("reference");
  ReferenceOptions& r = config.options<ReferenceOptions>();
  r.rays = rays;
  r.seed = seed;
  r.samples = SampleSet::PerPixel;  // jittered afresh per pixel: the noise a ray tracer has
  return prepareTechnique(config, scene);
}

// The equal-error search's oracle draws other random samples than the reference it is compared
// with, or it would match the reference's own noise and look better than it is.
uint64_t searchSeed(int rays) { return 1000003ull + uint64_t(rays); }
constexpr uint64_t kReferenceSeed = 1;

// The median wall-clock time of `runs` renders of every light.
double medianRenderMs(const PreparedTechnique& prepared, const Scene& scene, const View& view,
                      const EyeBuffers& eye, const RenderContext& context, int runs) {
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    double ms = 0;
    renderLights(prepared, scene, view, eye, context, ms);
    times.push_back(ms);
  }
  return medianOf(times);
}

// The row's strip: a technique whose every light's image equals an earlier one's (the wedge
// implementations agree pixel for pixel) links that strip instead of writing a copy; otherwise
// its strip is written (where asked for) and its images kept in `rendered` for the later ones.
void placeStrip(const FidelityOptions& o, const FidelityScene& out,
                const std::vector<Image<float>>& v, const std::vector<Image<float>>& reference,
                std::vector<std::pair<std::string, std::vector<Image<float>>>>& rendered,
                FidelityRow& row) {
  for (const auto& [earlier, images] : rendered)
    if (std::equal(v.begin(), v.end(), images.begin(), images.end(),
                   [](const Image<float>& a, const Image<float>& b) {
                     return compareExact(a, b).differing == 0;
                   })) {
      row.same_as = earlier;
      break;
    }
  if (!row.same_as.empty()) {
    for (const FidelityRow& r : out.rows)
      if (r.technique == row.same_as) row.strip = r.strip;
  } else if (!o.strip_dir.empty()) {
    const std::string file = fmt::format("{}-{}.png", out.label, row.technique);
    writeFidelityStrip((fs::path(o.strip_dir) / file).string(), v[0], reference[0],
                       o.heat_scale, o.strip_shrink);
    row.strip = o.strip_prefix + file;
  }
  if (row.same_as.empty()) rendered.emplace_back(row.technique, v);
}

FidelityScene measureScene(const FidelityOptions& o, const std::string& name, const Scene& scene,
                           const std::vector<std::string>& techniques, ProgressBar& progress) {
  auto log = [&](const std::string& line) {
    if (o.log) o.log(line);
  };
  FidelityScene out;
  out.name = displayName(name);
  out.label = sceneLabel(name);
  out.triangles = scene.triangleCount();
  out.lights = int(scene.lights.size());
  const View view = scene.camera.makeView(o.width, o.height);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats, o.simd);
  RenderContext context;
  context.simd = o.simd;
  context.show_progress = false;  // one bar for the whole run

  const auto oracle = prepareOracle(scene, o.oracle_rays, kReferenceSeed);
  const std::vector<Image<float>> reference =
      renderLights(*oracle, scene, view, eye, context, out.oracle_ms);
  log(fmt::format("{}: oracle {} rays: {:.0f} ms", out.label, o.oracle_rays, out.oracle_ms));
  progress.add();

  auto measureRays = [&](int rays) {
    RayErrorPoint p;
    p.rays = rays;
    const auto prepared = prepareOracle(scene, rays, searchSeed(rays));
    const std::vector<Image<float>> v = renderLights(*prepared, scene, view, eye, context, p.ms);
    p.penumbra_mae = fidelityError(v, reference, eye.depth.depth, o.tolerance).penumbra.mae;
    return p;
  };

  std::vector<std::pair<std::string, std::vector<Image<float>>>> rendered;  // distinct images
  for (const std::string& technique : techniques) {
    FidelityRow row;
    row.technique = technique;
    try {
      const auto prepared = prepareTechnique(TechniqueConfig(technique), scene);
      double first_ms = 0;
      const std::vector<Image<float>> v =
          renderLights(*prepared, scene, view, eye, context, first_ms);  // also the warm-up
      row.technique_ms = medianRenderMs(*prepared, scene, view, eye, context, o.timing_runs);
      row.error = fidelityError(v, reference, eye.depth.depth, o.tolerance);
      const int at = extendUntilReached(out.curve, row.error.penumbra.mae, o.max_search_rays,
                                        measureRays);
      if (at >= 0) {
        row.equal_error_rays = out.curve[size_t(at)].rays;
        row.equal_error_ms = out.curve[size_t(at)].ms;
        row.speed_ratio = row.technique_ms > 0 ? row.equal_error_ms / row.technique_ms : 0.0;
      }
      placeStrip(o, out, v, reference, rendered, row);
      log(fmt::format("{}: {}: penumbra MAE {:.4f}, {:.1f} ms, equal-error rays {}", out.label,
                      technique, row.error.penumbra.mae, row.technique_ms,
                      row.equal_error_rays > 0 ? fmt::format("{}", row.equal_error_rays)
                                               : fmt::format("> {}", o.max_search_rays)));
    } catch (const Error& e) {
      row.failure = e.what();
      log(fmt::format("{}: {}: not run: {}", out.label, technique, row.failure));
    }
    out.rows.push_back(std::move(row));
    progress.add();
  }
  return out;
}

}  // namespace

std::vector<std::string> fidelityTechniques() {
  std::vector<std::string> names;
  for (const TechniqueInfo& info : techniques())
    if (info.traits.soft && !info.traits.ray_traced) names.push_back(info.name);
  return names;
}

std::vector<std::string> fidelityScenes(const std::vector<std::string>& scene_dirs,
                                        std::vector<std::pair<std::string, std::string>>& skipped) {
  std::vector<std::string> scenes = builtinSceneNames();
  std::vector<std::string> files;
  for (const std::string& dir : scene_dirs) {
    std::vector<std::string> here;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file() && it->path().extension() == ".json") here.push_back(it->path());
    std::sort(here.begin(), here.end());
    files.insert(files.end(), here.begin(), here.end());
  }
  const std::string models = modelsDirectory();
  for (const std::string& file : files) {
    std::vector<std::string> missing;
    try {
      for (const std::string& model : sceneFileModels(file)) {
        std::error_code exists_ec;
        if (!fs::exists(modelPath(model), exists_ec)) missing.push_back(model);
      }
    } catch (const Error& e) {
      skipped.emplace_back(file, e.what());
      continue;
    }
    if (missing.empty()) {
      scenes.push_back(file);
    } else {
      skipped.emplace_back(file, fmt::format("missing {} in {}", fmt::join(missing, ", "), models));
    }
  }
  return scenes;
}

FidelityResult runFidelity(const FidelityOptions& options) {
  checkOptions(options);
  const auto start = std::chrono::steady_clock::now();
  ThreadLimit limit(options.threads);
  FidelityResult result;
  result.options = options;
  result.options.log = nullptr;
  const MachineInfo machine = machineInfo();
  result.cpu = machine.cpu_model;
  result.cores = machine.cores;
  result.threads = workerCount();
  result.simd_target = options.simd ? simdTargetName() : "scalar";
  result.date = utcNow();
  const std::vector<std::string> techniques =
      options.techniques.empty() ? fidelityTechniques() : options.techniques;
  ProgressBar progress("fidelity", options.scenes.size() * (techniques.size() + 1),
                       options.show_progress);
  for (const std::string& name : options.scenes) {
    Scene scene;
    try {
      scene = loadScene(name);
    } catch (const Error& e) {
      result.skipped.emplace_back(name, e.what());
      progress.add(techniques.size() + 1);
      continue;
    }
    if (scene.lights.empty()) {
      result.skipped.emplace_back(name, "the scene has no light");
      progress.add(techniques.size() + 1);
      continue;
    }
    result.scenes.push_back(measureScene(options, name, scene, techniques, progress));
  }
  progress.finish();
  result.seconds = secondsSince(start);
  return result;
}

}  // namespace penumbra
