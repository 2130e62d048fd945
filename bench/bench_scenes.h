#pragma once
// Scenes for the benchmarks, built once per process and shared by every benchmark binary file.
#include <string>

#include "scene/scene.h"

namespace penumbra {

// The built-in scene, scene file or mesh file `name` (as `penumbra render` takes it), built on
// first use, before any timing loop: building `fractal`
// (terrain, normals, adjacency) costs far more than a frame and is not what the benchmarks
// measure. Thread-safe; the reference stays valid for the process.
const Scene& benchScene(const std::string& name);

}  // namespace penumbra
