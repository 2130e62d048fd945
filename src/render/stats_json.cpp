#include "render/stats_json.h"

#include <fstream>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "render/image_io.h"

namespace penumbra {
namespace {

using nlohmann::json;

json statsToJson(const Stats& s) {
  json passes = json::array();
  for (const auto& [name, ms] : s.time_ms) passes.push_back({{"pass", name}, {"ms", ms}});
  return {
      {"pixels_rasterized", s.pixels_rasterized},
      {"z_reads", s.z_reads},
      {"stencil_writes", s.stencil_writes},
      {"tiles_tested", s.tiles_tested},
      {"tiles_culled", s.tiles_culled},
      {"tiles_accepted", s.tiles_accepted},
      {"silhouette_edges", s.silhouette_edges},
      {"wedges", s.wedges},
      {"triangles", s.triangles},
      {"rays", s.rays},
      {"penumbra_tests", s.penumbra_tests},
      {"penumbra_inside", s.penumbra_inside},
      {"time_ms", passes},
      {"total_ms", s.totalMs()},
  };
}

json vecToJson(const vec3& v) { return json::array({v.x, v.y, v.z}); }

// Mean visibility over the pixels where geometry is visible (background pixels are 1 by
// contract and would only dilute the number); NaN-free because visibility is in [0, 1].
double meanVisibility(const Image<float>& visibility, const EyeBuffers& eye) {
  if (visibility.size() != eye.primitive.size()) return 0.0;
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < visibility.size(); ++i) {
    if (eye.primitive[i] == kNoPrimitive) continue;
    sum += visibility[i];
    ++count;
  }
  return count ? sum / double(count) : 1.0;
}

int effectiveThreads(const FrameOptions& options) {
  return options.threads > 0 ? options.threads : workerCount();
}

std::string passList(const Stats& s) {
  std::string text;
  for (const auto& [name, ms] : s.time_ms) {
    text += fmt::format("{}{} {:.1f}", text.empty() ? "" : ", ", name, ms);
  }
  return text;
}

}  // namespace

MachineInfo machineInfo() {
  MachineInfo info;
  info.cpu_model = "unknown";
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    if (start != std::string::npos) info.cpu_model = line.substr(start);
    break;
  }
  info.cores = int(std::thread::hardware_concurrency());
  return info;
}

std::string volumeModeName(VolumeMode mode) {
  switch (mode) {
    case VolumeMode::Auto: return "auto";
    case VolumeMode::ZPass: return "zpass";
    case VolumeMode::ZFail: return "zfail";
  }
  return "unknown";
}

VolumeMode parseVolumeMode(const std::string& name) {
  for (VolumeMode mode : {VolumeMode::Auto, VolumeMode::ZPass, VolumeMode::ZFail}) {
    if (name == volumeModeName(mode)) return mode;
  }
  throw Error(fmt::format("unknown volume mode '{}' (known: auto, zpass, zfail)", name));
}

std::string describeTechnique(const TechniqueOptions& options) {
  const std::string name = techniqueName(options.kind);
  const char* stencil = options.two_level_stencil ? "" : ", one-level stencil";
  switch (options.kind) {
    case TechniqueKind::ShadowVolume:
      return fmt::format("{} ({}{})", name, volumeModeName(options.volume_mode), stencil);
    case TechniqueKind::Reference:
      return options.hard ? fmt::format("{} (hard)", name)
                          : fmt::format("{} ({} rays)", name, options.rays);
    case TechniqueKind::Wedge2002:
      return fmt::format("{} ({})", name, volumeModeName(options.volume_mode));
    case TechniqueKind::WedgeThreePass:
    case TechniqueKind::WedgeSinglePass:
      return fmt::format("{} ({}, cull {}, {}x{} tiles{})", name,
                         volumeModeName(options.volume_mode), cullModeName(options.cull),
                         1 << options.tile_level, 1 << options.tile_level,
                         options.cull == CullMode::Full ? stencil : "");
  }
  return name;
}

std::string frameStatsJson(const Scene& scene, const FrameOptions& options,
                           const FrameResult& result) {
  const MachineInfo machine = machineInfo();
  json lights = json::array();
  for (size_t i = 0; i < result.lights.size(); ++i) {
    json entry = {{"index", i}};
    if (i < scene.lights.size()) {
      entry["center"] = vecToJson(scene.lights[i].center);
      entry["radius"] = scene.lights[i].radius;
    }
    entry["mean_visibility"] = meanVisibility(result.lights[i].visibility, result.eye);
    entry["stats"] = statsToJson(result.lights[i].stats);
    lights.push_back(std::move(entry));
  }
  const TechniqueOptions& t = options.technique;
  const json doc = {
      {"scene", scene.name},
      {"triangles", scene.triangleCount()},
      {"meshes", scene.meshes.size()},
      {"width", result.view.width},
      {"height", result.view.height},
      {"technique",
       {{"name", techniqueName(t.kind)},
        {"description", describeTechnique(t)},
        {"volume_mode", volumeModeName(t.volume_mode)},
        {"rays", t.rays},
        {"hard", t.hard},
        {"seed", t.seed},
        {"cull", cullModeName(t.cull)},
        {"tile_size", 1 << t.tile_level},
        {"smooth_falloff", t.smooth_falloff},
        {"two_level_stencil", t.two_level_stencil}}},
      {"threads", effectiveThreads(options)},
      {"simd", t.simd},
      {"machine", {{"cpu", machine.cpu_model}, {"cores", machine.cores}}},
      {"eye_pass", statsToJson(result.eye_stats)},
      {"lights", lights},
      {"total", statsToJson(result.total)},
  };
  return doc.dump(2) + "\n";
}

void writeStatsJson(const std::string& path, const Scene& scene, const FrameOptions& options,
                    const FrameResult& result) {
  PENUMBRA_CHECK(!path.empty(), "stats output path is empty");
  createParentDirectories(path);
  const std::string text = frameStatsJson(scene, options, result);
  std::ofstream out(path, std::ios::binary);
  PENUMBRA_CHECK(out.good(), "cannot open stats file '{}' for writing", path);
  out << text;
  out.close();
  PENUMBRA_CHECK(!out.fail(), "cannot write stats file '{}'", path);
}

std::string frameSummaryLine(const Scene& scene, const FrameOptions& options,
                             const FrameResult& result) {
  std::string line = fmt::format("{} {}x{}, {} triangles, {}, {} threads{}: ", scene.name,
                                 result.view.width, result.view.height, scene.triangleCount(),
                                 describeTechnique(options.technique), effectiveThreads(options),
                                 options.technique.simd ? "" : ", scalar");
  line += fmt::format("eye {:.1f} ms", result.eye_stats.totalMs());
  // Passes of the total that are neither the eye pass's nor a light's (shading, outputs).
  std::map<std::string, int> accounted;
  for (const auto& pass : result.eye_stats.time_ms) ++accounted[pass.first];
  for (size_t i = 0; i < result.lights.size(); ++i) {
    const Stats& s = result.lights[i].stats;
    for (const auto& pass : s.time_ms) ++accounted[pass.first];
    line += fmt::format(", light {} {:.1f} ms", i, s.totalMs());
    if (s.time_ms.size() > 1) line += " (" + passList(s) + ")";
  }
  for (const auto& [name, ms] : result.total.time_ms) {
    auto it = accounted.find(name);
    if (it != accounted.end() && it->second > 0) {
      --it->second;
      continue;
    }
    line += fmt::format(", {} {:.1f} ms", name, ms);
  }
  line += fmt::format("; frame {:.1f} ms", result.total.totalMs());
  const Stats& c = result.total;
  line += fmt::format(
      " | pixels {}, z reads {}, stencil writes {}, tiles {} ({} culled, {} accepted whole), "
      "silhouette edges {}, wedges {}",
      c.pixels_rasterized, c.z_reads, c.stencil_writes, c.tiles_tested, c.tiles_culled,
      c.tiles_accepted, c.silhouette_edges, c.wedges);
  return line;
}

}  // namespace penumbra
