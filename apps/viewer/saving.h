#pragma once
// Saving what the viewer shows: the frame as `penumbra render` writes it (PNG from the rendered
// image, not read back from the window, so it matches the CLI bit for bit), every light's
// visibility as EXR, and the camera and lights as a scene file over the opened scene.
#include <string>

#include <penumbra/penumbra.h>

#include "viewer_model.h"

namespace penumbra::viewer {

// The scene a saved file names as its base: a built-in scene's name as is, a file's absolute
// path (so the saved file works from any folder).
std::string baseSceneName(const std::string& scene_argument);

// Writes the frame's colour image as PNG (core/image_io.h's writePng, as the CLI does).
void writeFrameScreenshot(const std::string& png_path, const FrameResult& frame);
// Writes light i's visibility to indexedOutputPath(exr_path, i), as `render --visibility` does.
void writeVisibilityExr(const std::string& exr_path, const FrameResult& frame);
// Writes the model's camera, lights and frame size over `base_scene` and returns the
// `penumbra render` command line that renders the same frame from it.
std::string saveSceneFile(const std::string& path, const Scene& scene, const ViewerModel& model,
                          const std::string& base_scene);

}  // namespace penumbra::viewer
