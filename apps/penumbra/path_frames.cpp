#include "path_frames.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra::cli {

std::string frameOutputPath(const std::string& path, int frame, int frame_count) {
  const int digits = std::max(4, int(fmt::format("{}", std::max(0, frame_count - 1)).size()));
  std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  p.replace_extension();
  return fmt::format("{}.{:0{}d}{}", p.string(), frame, digits, ext);
}

std::vector<int> framesToRender(const Scene& scene, bool all, int one) {
  if (!all && one < 0) return {};
  PENUMBRA_CHECK(!scene.path.empty(),
                 "scene '{}' has no camera or light path (give it a \"path\": "
                 "docs/scene-format.md)",
                 scene.name);
  if (!all) {
    PENUMBRA_CHECK(one < scene.path.frames,
                   "--frame {} is out of range: the path of scene '{}' has frames 0..{}", one,
                   scene.name, scene.path.frames - 1);
    return {one};
  }
  std::vector<int> frames(size_t(scene.path.frames));
  for (int k = 0; k < scene.path.frames; ++k) frames[size_t(k)] = k;
  return frames;
}

}  // namespace penumbra::cli
