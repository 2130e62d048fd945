#include <gtest/gtest.h>

#include "core/parallel.h"
#include "raster/eye_pass.h"
#include "raster/tile_kernels.h"
#include "scene/builtin_scenes.h"
#include "shadows/technique.h"
#include "shadows/volume/volume_technique.h"

namespace penumbra {
namespace test_volume_invariance {

struct VolumeRun {
  Image<float> visibility;
  Stats stats;
};

VolumeRun runVolumes(const Scene& scene, const View& view, int threads, bool simd, VolumeMode mode) {
  ThreadLimit limit(threads);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats, simd);
  TechniqueConfig o("volume", VolumeOptions{mode});
  RenderContext context;
  context.simd = simd;
  TechniqueResult r = renderShadows(o, scene, scene.lights[0], view, eye, context);
  r.stats.addCounters(eye_stats);
  return {std::move(r.visibility), r.stats};
}

// Counters are what the papers plot: they must be exact, the same for 1 or N threads and for
// the SIMD kernels and their scalar twins; so must every pixel.
TEST(ShadowVolumeInvariance, ThreadsAndSimdDoNotChangeImagesOrCounters) {
  for (const std::string& name : {std::string("columns"), std::string("fractal")}) {
    const Scene scene = builtinScene(name);
    const View view = scene.camera.makeView(320, 214);
    for (VolumeMode mode : {VolumeMode::ZPass, VolumeMode::ZFail}) {
      const VolumeRun base = runVolumes(scene, view, 1, false, mode);
      EXPECT_GT(base.stats.stencil_writes, 0u);
      EXPECT_GT(base.stats.silhouette_edges, 0u);
      for (int threads : {1, 2, 4}) {
        for (bool simd : {false, true}) {
          if (simd && !simdKernelsAvailable()) continue;
          const VolumeRun r = runVolumes(scene, view, threads, simd, mode);
          EXPECT_TRUE(r.visibility == base.visibility) << name << " threads " << threads << " simd " << simd;
          EXPECT_TRUE(r.stats.sameCounters(base.stats)) << name << " threads " << threads << " simd " << simd;
        }
      }
    }
  }
}

}  // namespace test_volume_invariance
}  // namespace penumbra
