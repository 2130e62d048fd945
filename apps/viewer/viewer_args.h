#pragma once
// The viewer's command line: `penumbra-view SCENE [--technique NAME] [technique options as
// `penumbra render` takes them] [viewer options]`.
#include <string>
#include <utility>
#include <vector>

namespace penumbra::viewer {

struct ViewerArgs {
  std::string scene;  // a built-in scene, a .json scene file or a mesh file
  std::string technique = "wedge-3pass";
  std::vector<std::pair<std::string, std::string>> technique_options;  // name, value
  int width = 0, height = 0;  // 0: the scene's settings
  int threads = 0;
  bool scalar = false;
  std::string script;
  int quit_after = 0;  // window frames after the script's end; 0: run until closed
  std::string screenshot;         // PNG of the frame area (the rendered image)
  std::string visibility;         // EXR per light, with the screenshot
  std::string window_screenshot;  // PNG of the whole window, panel included
  std::string save_scene;         // the camera and lights as a scene file, on quitting
  int bench_frames = 0;  // render this many full frames back to back, print their timings, quit
  bool help = false;
};

// Throws penumbra::Error naming the argument and what is wrong.
ViewerArgs parseViewerArgs(const std::vector<std::string>& argv);
std::string viewerUsage();

}  // namespace penumbra::viewer
