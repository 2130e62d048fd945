#pragma once
// Runs a technique and the oracle on the same eye pass, for tests against ground truth.
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "metrics/shadow_boundary.h"
#include "raster/eye_pass.h"
#include "scene/generators.h"
#include "scene/model_sources.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"

namespace penumbra::testing {

// A ground plane with a unit sphere hovering over it at height 2, one light (a point light by
// default): the small scene the eye-placement tests move around in.
inline Scene sphereOverGround(vec3 eye, vec3 target, vec3 light, float light_radius = 0.0f) {
  Scene s;
  s.name = "sphere-over-ground";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0), 20.0f));
  s.meshes.push_back(makeSphere(vec3(0, 2, 0), 1.0f, 32, 16));
  s.lights.push_back(Light{light, light_radius, vec3(1), 1.0f});
  s.camera.position = eye;
  s.camera.target = target;
  s.camera.fov_y = 60.0f;
  s.camera.near_plane = 0.05f;
  s.finalize();
  return s;
}

struct OracleComparison {
  BoundaryAgreement agreement;
  TechniqueResult technique;
  TechniqueResult oracle;
  EyeBuffers eye;
};

inline OracleComparison compareHardWithOracle(const Scene& scene, const View& view,
                                              const TechniqueConfig& config,
                                              size_t light_index = 0,
                                              const RenderContext& context = {}) {
  OracleComparison c;
  Stats eye_stats;
  c.eye = renderEyePass(scene, view, eye_stats, context.simd);
  const Light& light = scene.lights.at(light_index);
  c.technique = renderShadows(config, scene, light, view, c.eye, context);
  TechniqueConfig reference("reference");
  reference.options<ReferenceOptions>().hard = true;
  c.oracle = renderShadows(reference, scene, light, view, c.eye);
  c.agreement = compareHardShadows(c.technique.visibility, c.oracle.visibility, c.eye.depth.depth);
  return c;
}

// Whether every "models:" file the scene file names can be read (modelPath()): a user's cache
// may hold only the models npm ships, so tests over scene files skip the others one by one.
inline bool sceneModelsPresent(const std::filesystem::path& scene_file) {
  for (const std::string& name : sceneFileModels(scene_file.string())) {
    if (!std::filesystem::exists(modelPath(name))) return false;
  }
  return true;
}

// The folders of scene files the suites render: scenes/ (every file renders on a fresh clone)
// and tests/data/scenes/ (models the repository can neither ship nor fetch; skipped where no
// models folder holds them).
inline std::vector<std::filesystem::path> sceneFileFolders() {
  const std::filesystem::path root(PENUMBRA_SOURCE_DIR);
  return {root / "scenes", root / "tests" / "data" / "scenes"};
}

// Calls fn(path, scene) for every scene file of sceneFileFolders() whose models are present, in
// directory order; the others get a skip line and are counted. Returns {run, skipped}.
template <class Fn>
std::pair<int, int> forEachSceneFileWithModels(Fn&& fn) {
  std::pair<int, int> counts{0, 0};
  for (const std::filesystem::path& dir : sceneFileFolders()) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".json") continue;
      if (!sceneModelsPresent(entry.path())) {
        std::printf("[ SKIPPED  ] %s: its models are not in %s\n",
                    entry.path().filename().c_str(), modelsDirectory().c_str());
        ++counts.second;
        continue;
      }
      fn(entry.path(), loadSceneFile(entry.path().string()));
      ++counts.first;
    }
  }
  return counts;
}

// Path of a model ("models:" name), or empty when it is not available (tests then skip).
inline std::string sharedModel(const std::string& file) {
  const std::string p = modelPath(file);
  return std::filesystem::exists(p) ? p : std::string();
}

}  // namespace penumbra::testing
