// `exact` with the light touching a tessellated caster: the planes of many of the
// caster's triangles cut the light, and from points near the caster those triangles' parts
// toward the light reach past the light's nearest depth (pixel_edges.h, classifyCutting: not
// "in front"). The per-pixel quick reject (edge_screen_test.h) drops an edge with such a
// triangle only where it can prove the triangle in front of the light from the pixel; this is
// the case where that proof must fail. Compared with the oracle tracing the same fixed samples:
// identical up to ties, with the SIMD kernels and with the scalar twins.
//
// Release run time: about 0.2 s (96 x 64 pixels, N = 64: the oracle once, `exact` with and
// without SIMD).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "eye_frame_util.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/exact/exact_technique.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_exact_light_near_casters {

Image<float> renderWith(const TechniqueConfig& config, const testing::EyeFrame& f, bool simd) {
  const std::unique_ptr<PreparedTechnique> prepared = prepareTechnique(config, f.scene);
  RenderContext context;
  context.simd = simd;
  return prepared->render(f.scene.lights[0], f.view, f.eye, context).visibility;
}

// A globe of 24 x 12 quads (radius 0.5, centre 0.55 above a floor) under a light of radius 0.4
// whose ball dips some 0.07 into the globe's upper side (centres 0.83 apart), seen from above
// and to the side: the globe's lit cap, its terminator and the floor's penumbra next to it.
// With the quick reject's "in front" proof replaced by "always in front", 1237 of the 4687
// covered pixels differ from the oracle (checked when this test was written); with it, 1.
testing::EyeFrame lightNearGlobe() {
  Scene scene;
  scene.name = "light-near-globe";
  const uint32_t material = addMaterial(scene, "grey", vec3(0.7f));
  addMesh(scene, makeGroundPlane(vec3(0.0f), 4.0f), material);
  addMesh(scene, makeSphere(vec3(0.0f, 0.55f, 0.0f), 0.5f, 24, 12), material);
  addLight(scene, vec3(0.35f, 1.3f, 0.1f), 0.4f);
  scene.camera.position = vec3(1.6f, 1.9f, 2.2f);
  scene.camera.target = vec3(0.0f, 0.4f, 0.0f);
  scene.camera.near_plane = 0.05f;
  scene.finalize();
  return testing::makeEyeFrame(std::move(scene), 96, 64);
}

// If this failed, the quick reject would drop an edge that changes samples where a cutting
// triangle lies partly beyond the light's nearest depth: its "in front" proof (the corners'
// depth against |c - p| - r, widened for the shaded point's offset and float rounding) would
// be unsound, and pixels near the caster would come out too bright or too dark.
TEST(ExactLightNearCasters, QuickRejectKeepsEdgesOfTrianglesNotInFront) {
  const testing::EyeFrame f = lightNearGlobe();
  ExactOptions exact;
  exact.samples = 64;
  ReferenceOptions oracle;
  oracle.rays = 64;
  oracle.samples = SampleSet::Fixed;
  const Image<float> expected = renderWith(TechniqueConfig("reference", oracle), f, true);
  for (const bool simd : {true, false}) {
    const Image<float> got = renderWith(TechniqueConfig("exact", exact), f, simd);
    size_t covered = 0, differing = 0, penumbra = 0;
    for (size_t i = 0; i < got.size(); ++i) {
      if (!(f.eye.depth.depth[i] > 0.0f)) continue;
      ++covered;
      penumbra += expected[i] > 0.0f && expected[i] < 1.0f;
      differing += got[i] != expected[i];
    }
    std::printf("[ exact    ] light near globe (%s): %zu of %zu covered px differ, penumbra %zu\n",
                simd ? "SIMD" : "scalar", differing, covered, penumbra);
    // The scene must have a real penumbra, or the comparison proves little.
    EXPECT_GT(penumbra, 500u);
    // Ties (a sample on an edge's projection, a centre-count tie at a contact): a few pixels.
    EXPECT_LE(differing, 3u) << (simd ? "SIMD" : "scalar") << ": " << differing << " of "
                             << covered << " covered pixels differ from the oracle";
  }
}

}  // namespace test_exact_light_near_casters
}  // namespace penumbra
