#include "render/stats_json.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image_io.h"
#include "core/output_file.h"
#include "core/parallel.h"
#include "core/simd_dispatch.h"
#include "render/frame_timing.h"
#include "scene/mesh_report.h"

namespace penumbra {
namespace {

using nlohmann::json;

json statsToJson(const Stats& s) {
  json passes = json::array();
  for (const auto& [name, ms] : s.time_ms) passes.push_back({{"pass", name}, {"ms", ms}});
  json out = json::object();
  s.forEachCounter([&](const char* name, const char*, uint64_t value) { out[name] = value; });
  out["time_ms"] = passes;
  out["total_ms"] = s.totalMs();
  return out;
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

// What loading made of each mesh (scene/mesh_report.h), the numbers `render` prints per mesh.
json meshStatsJson(const Scene& scene) {
  json meshes = json::array();
  for (size_t i = 0; i < scene.meshes.size() && i < scene.adjacency.size(); ++i) {
    const MeshReport r = reportMesh(scene.meshes[i], scene.adjacency[i]);
    meshes.push_back({{"name", r.name},
                      {"from_file", r.from_file},
                      {"file_vertices", r.file_vertices},
                      {"file_triangles", r.file_triangles},
                      {"triangles", r.triangles},
                      {"welded_vertices", r.welded_vertices},
                      {"open_edges", r.open_edges},
                      {"non_manifold_edges", r.non_manifold_edges},
                      {"degenerate_dropped", r.degenerate_dropped},
                      {"components", r.components},
                      {"warnings", scene.meshes[i].file_counts.warnings}});
  }
  return meshes;
}

int effectiveThreads(const FrameOptions& options) {
  return options.context.threads > 0 ? options.context.threads : workerCount();
}

std::string passList(const Stats& s) {
  std::string text;
  for (const auto& [name, ms] : s.time_ms) {
    text += (text.empty() ? "" : ", ") + passTimeText(name, ms, 1);
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
  const TechniqueConfig& t = options.technique;
  json technique = {{"name", t.name()},
                    {"description", t.describe()},
                    {"soft", t.info().traits.soft},
                    {"exact", t.info().traits.exact}};
  for (const OptionSpec& spec : t.info().options.specs()) {
    std::string key = spec.name;
    std::replace(key.begin(), key.end(), '-', '_');
    const std::string value = t.get(spec.name);
    switch (spec.kind) {
      case OptionKind::Flag: technique[key] = value == "true"; break;
      case OptionKind::Integer: technique[key] = std::stoll(value); break;
      case OptionKind::Choice: technique[key] = value; break;
      case OptionKind::Number: technique[key] = std::stod(value); break;
    }
  }
  const json doc = {
      {"scene", scene.name},
      {"triangles", scene.triangleCount()},
      {"meshes", scene.meshes.size()},
      {"mesh_stats", meshStatsJson(scene)},
      {"width", result.view.width},
      {"height", result.view.height},
      {"technique", technique},
      {"threads", effectiveThreads(options)},
      // What ran, not what was asked: PENUMBRA_SIMD=off or a scalar-only build overrides it.
      {"simd", useSimd(options.context.simd)},
      {"simd_target", useSimd(options.context.simd) ? simdTargetName() : "scalar"},
      {"caster_culling", casterCullingName(options.context.caster_culling)},
      {"occlusion_culling", occlusionCullingName(options.occlusion_culling)},
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
  writeFileAtomically(path, frameStatsJson(scene, options, result), "stats file");
}

std::string frameSummaryLine(const Scene& scene, const FrameOptions& options,
                             const FrameResult& result) {
  std::string line = fmt::format("{} {}x{}, {} triangles, {}, {} threads{}: ", scene.name,
                                 result.view.width, result.view.height, scene.triangleCount(),
                                 options.technique.describe(), effectiveThreads(options),
                                 useSimd(options.context.simd) ? "" : ", scalar");
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
    line += ", " + passTimeText(name, ms, 1) + " ms";
  }
  line += fmt::format("; frame {:.1f} ms", result.total.totalMs());
  // Every counter the frame touched, shared or the technique's own, by its name with spaces.
  const char* separator = " | ";
  result.total.forEachCounter([&](const char* counter, const char*, uint64_t value) {
    if (value == 0) return;
    std::string name = counter;
    std::replace(name.begin(), name.end(), '_', ' ');
    line += fmt::format("{}{} {}", separator, name, value);
    separator = ", ";
  });
  return line;
}

}  // namespace penumbra
