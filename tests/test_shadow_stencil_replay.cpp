// stencilContributionAt (rasterizer.h) tells a pass what the stencil pass added at one pixel for
// one polygon; the exact soft shadow volumes replay it for the quads near a pixel to move the
// stencil's count from the depth-buffer point to the oracle's ray origin. Replayed over every
// polygon the stencil pass set up (StencilQuads), it must give the stencil itself, bit for bit.
#include <gtest/gtest.h>

#include "eye_frame_util.h"
#include "raster/rasterizer.h"
#include "scene/builtin_scenes.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace test_shadow_stencil_replay {

// Sums the replayed contributions of every polygon at every pixel. If this failed, the replay
// would differ from the kernels (tile origin of the depth steps, edge functions, depth rule,
// owners), and a pass relying on it would correct counts the stencil never had.
void expectReplayGivesTheStencil(const std::string& name, Scene scene, VolumeMode mode) {
  const testing::EyeFrame f = testing::makeEyeFrame(std::move(scene), 97, 65);
  for (const bool skip_own_quads : {false, true}) {
    StencilQuads quads;
    ShadowStencilOptions options;
    options.mode = mode;
    options.policy = CasterPolicy::TwoSided;
    options.skip_own_quads = skip_own_quads;
    options.quads = &quads;
    Stats stats;
    const Image<int32_t> stencil =
        shadowStencil(f.scene, f.scene.lights.at(0).center, f.view, f.eye, options, stats);
    ASSERT_FALSE(quads.setup.empty()) << name;
    ASSERT_EQ(quads.first.size(), size_t(sceneEdgeOffsets(f.scene).back()) + 1) << name;
    size_t differing = 0, nonzero = 0;
    for (int y = 0; y < f.view.height; ++y) {
      for (int x = 0; x < f.view.width; ++x) {
        int32_t sum = 0;
        for (const SetupTriangle& t : quads.setup)
          sum += stencilContributionAt(t, x, y, f.eye.depth,
                                       skip_own_quads ? &f.eye.primitive : nullptr);
        differing += sum != stencil.at(x, y);
        nonzero += stencil.at(x, y) != 0;
      }
    }
    EXPECT_EQ(differing, 0u) << name << ", skip_own_quads " << skip_own_quads;
    EXPECT_GT(nonzero, 100u) << name << ": too few shadowed pixels for the test to mean much";
  }
}

TEST(ShadowStencilReplay, EveryPolygonReplayedGivesTheStencil) {
  for (const char* name : {"columns", "spheres", "year2002"}) {
    expectReplayGivesTheStencil(name, builtinScene(name), VolumeMode::Auto);
    expectReplayGivesTheStencil(std::string(name) + " z-fail", builtinScene(name),
                                VolumeMode::ZFail);
  }
}

// The quads grouped by scene edge are exactly the polygons that are not caps. If this failed,
// a pass looking up an edge's quad would miss pieces of it or get another edge's.
TEST(ShadowStencilReplay, QuadsAreGroupedByTheirEdge) {
  const testing::EyeFrame f = testing::makeEyeFrame(builtinScene("columns"), 97, 65);
  StencilQuads quads;
  ShadowStencilOptions options;
  options.mode = VolumeMode::ZPass;
  options.policy = CasterPolicy::TwoSided;
  options.quads = &quads;
  Stats stats;
  shadowStencil(f.scene, f.scene.lights.at(0).center, f.view, f.eye, options, stats);
  // z-pass has no caps: every polygon belongs to one edge's quad.
  EXPECT_EQ(quads.pieces.size(), quads.setup.size());
  std::vector<int> seen(quads.setup.size(), 0);
  size_t edges_with_quads = 0;
  for (size_t e = 0; e + 1 < quads.first.size(); ++e) {
    edges_with_quads += quads.first[e + 1] > quads.first[e];
    for (uint32_t k = quads.first[e]; k < quads.first[e + 1]; ++k) ++seen[quads.pieces[k]];
  }
  for (const int s : seen) EXPECT_EQ(s, 1);
  EXPECT_GT(edges_with_quads, 100u);
  EXPECT_LE(edges_with_quads, stats.silhouette_edges);
}

}  // namespace test_shadow_stencil_replay
}  // namespace penumbra
