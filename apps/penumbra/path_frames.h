#pragma once
// `penumbra render --path / --frame K / --list-frames`: which frames of a scene's camera and
// light path (scene/path.h) to render, and the numbered file each frame's outputs go to.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace penumbra::cli {

// Frame `frame` of `path`'s file: "out/city.png" -> "out/city.0007.png", the number padded to
// the digits of the path's last frame (at least 4), so that the files sort in frame order.
std::string frameOutputPath(const std::string& path, int frame, int frame_count);

// The frames to render: every frame of the path (`all`), frame `one` (>= 0), or none of the
// path (an empty list: the scene's own camera and lights). Throws penumbra::Error naming the
// scene when it has no path or `one` is out of range.
std::vector<int> framesToRender(const Scene& scene, bool all, int one);

}  // namespace penumbra::cli
