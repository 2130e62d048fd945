#include "saving.h"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra::viewer {

std::string baseSceneName(const std::string& scene_argument) {
  if (isBuiltinScene(scene_argument)) return scene_argument;
  return std::filesystem::absolute(scene_argument).lexically_normal().string();
}

void writeFrameScreenshot(const std::string& png_path, const FrameResult& frame) {
  writePng(png_path, frame.color);
}

void writeVisibilityExr(const std::string& exr_path, const FrameResult& frame) {
  for (size_t i = 0; i < frame.lights.size(); ++i) {
    writeExr(indexedOutputPath(exr_path, i), frame.lights[i].visibility);
  }
}

std::string saveSceneFile(const std::string& path, const Scene& scene, const ViewerModel& model,
                          const std::string& base_scene) {
  Scene shown = scene;
  shown.camera = model.camera;
  shown.lights = model.lights;
  shown.settings.width = model.width;
  shown.settings.height = model.height;
  writeSceneOverBase(path, shown, base_scene);
  return fmt::format("penumbra render {} {}", path, fmt::join(renderFlags(model), " "));
}

}  // namespace penumbra::viewer
