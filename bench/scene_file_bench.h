#pragma once
// Warm frames of scenes named on the command line (penumbra_bench --scene FILE): any scene file,
// mesh file or built-in scene, not only the ones compiled into the other benchmarks.
#include <string>
#include <vector>

namespace penumbra {

// Takes every "--scene=X" / "--scene X" and "--technique=NAME" out of argv (Google Benchmark
// refuses arguments it does not know) and registers SceneFrame/<scene>/<technique> for each
// scene and technique (default: wedge-3pass and volume), at the scene's own image size.
void registerSceneFileBenchmarks(int& argc, char** argv);

}  // namespace penumbra
