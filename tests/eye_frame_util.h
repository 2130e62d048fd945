#pragma once
// A scene with its view and eye pass, the input every technique test starts from.
#include <utility>

#include "raster/eye_pass.h"
#include "scene/scene.h"

namespace penumbra::testing {

struct EyeFrame {
  Scene scene;
  View view;
  EyeBuffers eye;
};

inline EyeFrame makeEyeFrame(Scene scene, int width, int height, bool simd = true) {
  EyeFrame f;
  f.scene = std::move(scene);
  f.view = f.scene.camera.makeView(width, height);
  Stats stats;
  f.eye = renderEyePass(f.scene, f.view, stats, simd);
  return f;
}

}  // namespace penumbra::testing
