// The eye pass's delay stream (raster/delay_stream.h) may only remove work: every depth,
// primitive id and tile range must be what the plain pass draws, at every ring size, SIMD or
// scalar, and it must cull where later triangles hide earlier ones.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/parallel.h"
#include "raster/delay_stream.h"
#include "raster/depth_pass.h"
#include "raster/eye_pass.h"
#include "raster_test_util.h"
#include "scene/builtin_scenes.h"

namespace penumbra {
namespace test_raster_delay_stream {

using testing::screenToClip;
using testing::TestRandom;

struct DepthFrame {
  DepthBuffer depth;
  Image<uint32_t> primitive;
  Stats stats;
};

DepthFrame draw(const ClipTriangles& tris, int width, int height, size_t ring_bytes,
                bool simd = true) {
  DepthFrame f;
  f.depth.depth.resize(width, height, 0.0f);
  f.primitive.resize(width, height, kNoPrimitive);
  rasterizeDepth(tris, f.depth, f.primitive, f.stats,
                 DepthPassOptions{.simd = simd, .delay_stream_bytes = ring_bytes,
                                  .depth_complexity = true});
  return f;
}

// Depth, ids and every level's tile z-min/z-max equal bit for bit.
void expectSameBuffers(const DepthFrame& plain, const DepthFrame& delayed, const char* what) {
  EXPECT_TRUE(plain.depth.depth == delayed.depth.depth) << what;
  EXPECT_TRUE(plain.primitive == delayed.primitive) << what;
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    EXPECT_TRUE(plain.depth.tileRange(level).zmin == delayed.depth.tileRange(level).zmin)
        << what << " level " << level;
    EXPECT_TRUE(plain.depth.tileRange(level).zmax == delayed.depth.tileRange(level).zmax)
        << what << " level " << level;
  }
}

// Triangles of every size at random depths, large ones among them, with depth ties (a quarter
// of them lie at depth exactly 0.5) and degenerate ones (zero area, a vertex at w = 0, NaN).
ClipTriangles mixedSoup(int count, int width, int height, uint64_t seed) {
  TestRandom rng(seed);
  ClipTriangles tris;
  for (int t = 0; t < count; ++t) {
    const double cx = rng.uniform(-20, width + 20), cy = rng.uniform(-20, height + 20);
    const double size = t % 17 == 0 ? rng.uniform(60, 300) : rng.uniform(1, 40);
    const bool tie = t % 4 == 0;
    for (int k = 0; k < 3; ++k) {
      tris.clip.push_back(screenToClip(cx + rng.uniform(-size, size),
                                       cy + rng.uniform(-size, size),
                                       tie ? 0.5 : rng.uniform(0.01, 1.0), width, height));
    }
    if (t % 29 == 0) tris.clip.back() = tris.clip[tris.clip.size() - 2];  // zero area
    if (t % 31 == 0) tris.clip.back() = vec4(0, 0, 0, 0);
    if (t % 37 == 0) tris.clip.back().x = std::nanf("");
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  return tris;
}

// One triangle at constant depth d whose inside holds the whole screen (one triangle: the
// occlusion cells a quad's diagonal crosses are covered whole by neither of its halves).
void addCover(ClipTriangles& tris, double d, int32_t id) {
  const uint32_t v = uint32_t(tris.clip.size());
  tris.clip.push_back(vec4(-1.0f, -1.0f, float(d), 1.0f));
  tris.clip.push_back(vec4(3.0f, -1.0f, float(d), 1.0f));
  tris.clip.push_back(vec4(-1.0f, 3.0f, float(d), 1.0f));
  tris.add(v, v + 1, v + 2, id);
}

// The same screen covered by two triangles (a quad) at constant depth d: the cells its diagonal
// crosses are filled only by the two together.
void addQuad(ClipTriangles& tris, double d, int32_t id) {
  const uint32_t v = uint32_t(tris.clip.size());
  tris.clip.push_back(vec4(-1.0f, -1.0f, float(d), 1.0f));
  tris.clip.push_back(vec4(1.0f, -1.0f, float(d), 1.0f));
  tris.clip.push_back(vec4(1.0f, 1.0f, float(d), 1.0f));
  tris.clip.push_back(vec4(-1.0f, 1.0f, float(d), 1.0f));
  tris.add(v, v + 1, v + 2, id);
  tris.add(v, v + 2, v + 3, id + 1);
}

// Every ring size, from one triangle to more than the scene: a culled triangle that could
// have kept a pixel (a tie with a later triangle, a bound taken on the wrong side of a float
// rounding) would show here as a changed depth or id.
TEST(DelayStream, BuffersEqualThePlainPassAtEveryRingSize) {
  const int width = 203, height = 117;  // not multiples of the bin tile or the cell
  const ClipTriangles tris = mixedSoup(3000, width, height, 7);
  const DepthFrame plain = draw(tris, width, height, 0);
  for (const size_t bytes : {size_t(1), kDelayStreamTriangleBytes, 2 * kDelayStreamTriangleBytes,
                             size_t(7 * 52), size_t(4096), size_t(65536), size_t(1) << 30}) {
    const DepthFrame delayed = draw(tris, width, height, bytes);
    expectSameBuffers(plain, delayed, "ring bytes");
    EXPECT_LE(delayed.stats.pixels_rasterized, plain.stats.pixels_rasterized) << bytes;
    EXPECT_LE(delayed.stats.counter("eye_depth_passes"), plain.stats.counter("eye_depth_passes"))
        << bytes;
    EXPECT_EQ(delayed.stats.counter("eye_covered_pixels"),
              plain.stats.counter("eye_covered_pixels"));
  }
}

// The scalar twins and one thread: the stream's decisions do not depend on either.
TEST(DelayStream, ScalarAndOneThreadGiveTheSameBuffersAndCounts) {
  const int width = 160, height = 96;
  const ClipTriangles tris = mixedSoup(2000, width, height, 3);
  const DepthFrame plain = draw(tris, width, height, 0, false);
  const DepthFrame simd = draw(tris, width, height, 4096, true);
  DepthFrame one;
  {
    ThreadLimit limit(1);
    one = draw(tris, width, height, 4096, false);
  }
  expectSameBuffers(plain, one, "scalar, one thread");
  expectSameBuffers(simd, one, "SIMD against scalar");
  EXPECT_TRUE(simd.stats.sameCounters(one.stats));
}

// Many hidden triangles, then the occluder: only a ring that still holds the hidden triangles
// when the occluder enters can cull them. A ring of one triangle is the early z-max test in
// submission order: it may skip pixels but never a depth pass, since whatever it culls would
// have failed the depth test at each pixel anyway.
ClipTriangles hiddenThenOccluder(int width, int height, int hidden, bool quad) {
  ClipTriangles tris;
  TestRandom rng(1);
  for (int t = 0; t < hidden; ++t) {
    const double cx = rng.uniform(0, width), cy = rng.uniform(0, height);
    for (int k = 0; k < 3; ++k)
      tris.clip.push_back(screenToClip(cx + rng.uniform(-12, 12), cy + rng.uniform(-12, 12),
                                       rng.uniform(0.05, 0.3), width, height));
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  if (quad)
    addQuad(tris, 0.6, hidden);
  else
    addCover(tris, 0.6, hidden);
  return tris;
}

TEST(DelayStream, CullsTrianglesALaterOccluderHides) {
  const int width = 128, height = 96, hidden = 400;
  for (const bool quad : {false, true}) {
    SCOPED_TRACE(quad ? "two triangles fill the cells together" : "one triangle covers all");
    const ClipTriangles tris = hiddenThenOccluder(width, height, hidden, quad);
    const DepthFrame plain = draw(tris, width, height, 0);
    const DepthFrame one = draw(tris, width, height, 1);
    const DepthFrame whole = draw(tris, width, height, size_t(1) << 20);
    expectSameBuffers(plain, one, "ring of one triangle");
    expectSameBuffers(plain, whole, "ring holding the scene");
    EXPECT_EQ(one.stats.counter("eye_depth_passes"), plain.stats.counter("eye_depth_passes"));
    EXPECT_LT(one.stats.counter("delay_culled_pairs"), whole.stats.counter("delay_culled_pairs"));
    EXPECT_GE(whole.stats.counter("delay_culled_pairs"), uint64_t(hidden));
    // Every hidden triangle goes: each pixel passes the depth test once, for the occluder.
    const uint64_t covered = whole.stats.counter("eye_covered_pixels");
    EXPECT_EQ(covered, uint64_t(width * height));
    EXPECT_EQ(whole.stats.counter("eye_depth_passes"), covered);
    EXPECT_LT(whole.stats.pixels_rasterized, plain.stats.pixels_rasterized / 2);
    for (size_t p = 0; p < whole.primitive.size(); ++p)
      ASSERT_GE(whole.primitive[p], uint32_t(hidden)) << "a hidden triangle won pixel " << p;
  }
}

// At a tie the earlier triangle keeps the pixel: an occluder at exactly the depth of the
// triangles before it must not cull them.
TEST(DelayStream, KeepsEarlierTrianglesAtTheOccludersDepth) {
  const int width = 64, height = 64;
  ClipTriangles tris;
  for (int t = 0; t < 20; ++t) {
    const double x = 3.0 * t, y = 2.0 * t;
    tris.clip.push_back(screenToClip(x, y, 0.4, width, height));
    tris.clip.push_back(screenToClip(x + 30, y, 0.4, width, height));
    tris.clip.push_back(screenToClip(x, y + 30, 0.4, width, height));
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  addCover(tris, 0.4, 20);
  const DepthFrame plain = draw(tris, width, height, 0);
  const DepthFrame whole = draw(tris, width, height, size_t(1) << 20);
  expectSameBuffers(plain, whole, "ties");
  EXPECT_EQ(whole.stats.counter("delay_culled_pairs"), 0u);
}

// Without a stream and without asking, the eye pass counts nothing new (the golden frame
// digests hold its counters).
TEST(DelayStream, OffCountsNothingNew) {
  const int width = 64, height = 48;
  const ClipTriangles tris = mixedSoup(200, width, height, 2);
  DepthFrame f;
  f.depth.depth.resize(width, height, 0.0f);
  f.primitive.resize(width, height, kNoPrimitive);
  rasterizeDepth(tris, f.depth, f.primitive, f.stats, DepthPassOptions{});
  EXPECT_TRUE(f.stats.declared.empty());
  EXPECT_EQ(delayStreamTriangles(0), 0u);
  EXPECT_EQ(delayStreamTriangles(1), 1u);
  EXPECT_EQ(delayStreamTriangles(2 * kDelayStreamTriangleBytes + 1), 2u);
}

// Every small built-in scene through the eye pass (each technique's input), at rings of one
// triangle and 64 KB: the same buffers.
TEST(DelayStream, EyePassOfEveryBuiltInSceneIsUnchanged) {
  for (const char* name : {"spheres", "columns", "fractal", "year2002", "multilight"}) {
    const Scene scene = builtinScene(name);
    const View view = scene.camera.makeView(200, 130);
    Stats plain_stats;
    const EyeBuffers plain = renderEyePass(scene, view, plain_stats, true);
    for (const size_t bytes : {size_t(1), size_t(64) << 10}) {
      Stats stats;
      const EyeBuffers delayed =
          renderEyePass(scene, view, stats, DepthPassOptions{.delay_stream_bytes = bytes});
      EXPECT_TRUE(plain.depth.depth == delayed.depth.depth) << name << " " << bytes;
      EXPECT_TRUE(plain.primitive == delayed.primitive) << name << " " << bytes;
      for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
        EXPECT_TRUE(plain.depth.tileRange(level).zmin == delayed.depth.tileRange(level).zmin);
        EXPECT_TRUE(plain.depth.tileRange(level).zmax == delayed.depth.tileRange(level).zmax);
      }
    }
  }
}

// A built-in scene through the eye pass: same buffers with the stream as without.
TEST(DelayStream, EyePassOfABuiltInSceneIsUnchanged) {
  const Scene scene = builtinScene("city:1");
  const View view = scene.camera.makeView(320, 180);
  Stats plain_stats, delayed_stats;
  const EyeBuffers plain = renderEyePass(scene, view, plain_stats, true);
  const EyeBuffers delayed = renderEyePass(
      scene, view, delayed_stats, DepthPassOptions{.delay_stream_bytes = size_t(256) << 10});
  EXPECT_TRUE(plain.depth.depth == delayed.depth.depth);
  EXPECT_TRUE(plain.primitive == delayed.primitive);
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level)
    EXPECT_TRUE(plain.depth.tileRange(level).zmax == delayed.depth.tileRange(level).zmax);
  EXPECT_GT(delayed_stats.counter("delay_culled_pairs"), 0u);
  EXPECT_LT(delayed_stats.pixels_rasterized, plain_stats.pixels_rasterized);
}

}  // namespace test_raster_delay_stream
}  // namespace penumbra
