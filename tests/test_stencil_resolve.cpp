// The row resolve of a hard stencil (src/shadows/stages/stencil/stencil_resolve.h): its SIMD
// version, its scalar twin and resolvedPixel's rule (facing_away.h) give the same visibility on
// every pixel (with the SIMD kernels switched off, the scalar twin against the rule).
#include <gtest/gtest.h>

#include "raster/eye_pass.h"
#include "raster_test_util.h"
#include "scene/builtin_scenes.h"
#include "shadows/stages/stencil/stencil_resolve.h"

namespace penumbra {
namespace test_stencil_resolve {

// `columns` at a width that is no multiple of a vector: rows hold the background, triangles
// facing away from the light, runs of one triangle and single pixels of many (the columns'
// thin facets), and a stencil of runs and isolated values. A difference means a vector showing
// one triangle was decided by another pixel's facing, a lane past the row's end was written, or
// the twins read the stencil differently (a null stencil is all 0).
TEST(StencilResolve, SimdScalarAndTheRuleAgreeOnEveryPixel) {
  const Scene scene = builtinScene("columns");
  const View view = scene.camera.makeView(203, 117);
  Stats stats;
  const EyeBuffers eye = renderEyePass(scene, view, stats);
  const Light& light = scene.lights.at(0);
  const FacingAway away(scene, light, view);
  testing::TestRandom rng(5);
  std::vector<int32_t> stencil(size_t(view.width));
  size_t background = 0, facing_away = 0, shadowed = 0, lit = 0;
  for (int y = 0; y < view.height; ++y) {
    const uint32_t* ids = eye.primitive.row(y);
    for (int x = 0; x < view.width;) {  // runs of 1 to 40 equal values
      const int32_t value = rng.uniform() < 0.5 ? 0 : int32_t(rng.uniform(-3, 3));
      for (int run = 1 + int(rng.uniform(0, 40)); run > 0 && x < view.width; --run)
        stencil[size_t(x++)] = value;
    }
    const int32_t* const stencils[] = {stencil.data(), nullptr};
    for (const int32_t* s : stencils) {
      // One pixel more than the row: a lane written past the end would change it.
      std::vector<float> simd(size_t(view.width) + 1, -1.0f), scalar(simd);
      resolveStencilRow(away, ids, s, simd.data(), view.width, true);
      const StencilSegment whole{0, view.width, s, 0};
      resolveStencilRowsScalar(away, {ids, 0, scalar.data(), 0, 1, &whole, 1});
      ASSERT_EQ(simd, scalar) << "row " << y;
      for (int x = 0; x < view.width; ++x) {
        const float rule = resolvedPixel(away, ids[x], [&] {
          return s != nullptr && s[x] != 0 ? 0.0f : 1.0f;
        });
        ASSERT_EQ(scalar[size_t(x)], rule) << "pixel " << x << ", " << y;
        if (s == nullptr) continue;
        if (ids[x] == kNoPrimitive) {
          ++background;
        } else if (away(ids[x])) {
          ++facing_away;
        } else {
          ++(s[x] != 0 ? shadowed : lit);
        }
      }
    }
  }
  // Every case of the rule was met.
  EXPECT_GT(background, 0u);
  EXPECT_GT(facing_away, 0u);
  EXPECT_GT(shadowed, 0u);
  EXPECT_GT(lit, 0u);
}

// A block of rows in segments, as hierarchical-volume resolves a row of bin tiles: pieces with
// stencils of their own (tile-sized, 32 elements a row) between runs without one, over rows of
// the frame's images. Each pixel must follow the rule with its own segment's stencil row: a
// difference means a segment read another's stencil or row, or wrote outside its columns.
TEST(StencilResolve, SegmentsReadTheirOwnStencilRows) {
  const Scene scene = builtinScene("columns");
  const View view = scene.camera.makeView(203, 117);
  Stats stats;
  const EyeBuffers eye = renderEyePass(scene, view, stats);
  const FacingAway away(scene, scene.lights.at(0), view);
  testing::TestRandom rng(11);
  constexpr int kRows = 20, kTile = 32;
  // Columns [0, 203) as: a run without stencil, a 32-wide tile, another, a run, a 11-wide tile.
  const std::vector<std::pair<int, int>> pieces = {{0, 50}, {50, 32}, {82, 32}, {114, 78},
                                                   {192, 11}};
  std::vector<std::vector<int32_t>> tiles(pieces.size());
  std::vector<StencilSegment> segments;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const bool own = k == 1 || k == 2 || k == 4;
    if (own) {
      tiles[k].resize(size_t(kTile) * kRows);
      for (int32_t& v : tiles[k]) v = rng.uniform() < 0.5 ? 0 : int32_t(rng.uniform(-3, 3));
    }
    segments.push_back({pieces[k].first, pieces[k].second, own ? tiles[k].data() : nullptr,
                        own ? size_t(kTile) : 0});
  }
  const int y0 = 40;
  for (const bool simd : {true, false}) {
    Image<float> out(view.width, view.height, -1.0f);
    const StencilResolveRows block{eye.primitive.row(y0), size_t(view.width), out.row(y0),
                                   size_t(view.width), kRows, segments.data(), segments.size()};
    if (simd)
      resolveStencilRows(away, block, true);
    else
      resolveStencilRowsScalar(away, block);
    for (int y = 0; y < view.height; ++y)
      for (int x = 0; x < view.width; ++x) {
        if (y < y0 || y >= y0 + kRows) {
          ASSERT_EQ(out.at(x, y), -1.0f) << "written outside the block at " << x << ", " << y;
          continue;
        }
        size_t k = 0;
        while (x >= segments[k].x0 + segments[k].n) ++k;
        const StencilSegment& g = segments[k];
        const float rule = resolvedPixel(away, eye.primitive.at(x, y), [&] {
          return g.stencil != nullptr &&
                         g.stencil[size_t(y - y0) * g.stencil_stride + size_t(x - g.x0)] != 0
                     ? 0.0f
                     : 1.0f;
        });
        ASSERT_EQ(out.at(x, y), rule) << (simd ? "simd" : "scalar") << ", pixel " << x << ", "
                                      << y;
      }
  }
}

}  // namespace test_stencil_resolve
}  // namespace penumbra
