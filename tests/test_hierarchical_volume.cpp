// Hierarchical shadow volumes and the depth-bounds baseline (src/shadows/hierarchical/) against
// the per-pixel stencil of `volume`: the same stencil on every pixel, z-pass and z-fail, on every
// built-in scene, with the eye inside a volume and the light in the view; and their counters,
// on a hand-made case whose numbers are worked out below.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/parallel.h"
#include "raster/eye_pass.h"
#include "raster/fixed_point.h"
#include "raster/rasterizer.h"
#include "raster/tile_kernels.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_file.h"
#include "shadow_test_util.h"
#include "shadows/hierarchical/tiled_volume_stencil.h"
#include "shadows/hierarchical/volume_set.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace test_hierarchical_volume {

using testing::sceneModelsPresent;
using testing::sphereOverGround;

// Every light of `scene`: the tiled stencils (both cullings, the given tile levels) must equal
// the per-pixel stencil on every pixel. A difference means a tile was decided by its sample
// while a volume's boundary crossed it (hierarchical), or a tile was skipped where a volume
// polygon could still change the count (depth bounds).
void expectSameStencils(const Scene& scene, const View& view, VolumeMode mode,
                        const std::vector<int>& levels, const std::string& what) {
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const vec3 centre = scene.lights[l].center;
    ShadowStencilOptions per_pixel;
    per_pixel.mode = mode;
    Stats per_pixel_stats;
    const Image<int32_t> expected =
        shadowStencil(scene, centre, view, eye, per_pixel, per_pixel_stats);
    Stats set_stats;
    const ShadowVolumeSet volumes = buildShadowVolumes(scene, centre, view, eye, mode, set_stats);
    for (int variant = 0; variant < 3; ++variant)
      for (int level : levels) {
        // Depth bounds; hierarchical as the thesis (every tile classified); hierarchical with
        // the default dense limit (dense volumes drawn per pixel, unclassified).
        const VolumeCulling culling =
            variant == 0 ? VolumeCulling::DepthBounds : VolumeCulling::Hierarchical;
        TiledVolumeStencilOptions options;
        options.culling = culling;
        options.tile_level = level;
        options.dense_limit = variant == 1 ? 0 : options.dense_limit;
        Stats stats;
        const Image<int32_t> stencil = tiledVolumeStencil(volumes, eye.depth, options, stats);
        size_t differing = 0;
        for (size_t i = 0; i < stencil.size(); ++i) differing += stencil[i] != expected[i];
        EXPECT_EQ(differing, 0u) << what << ", light " << l << ", mode "
                                 << volumeModeName(mode) << ", "
                                 << (culling == VolumeCulling::Hierarchical ? "hierarchical"
                                                                            : "depth bounds")
                                 << ", dense limit " << options.dense_limit
                                 << ", tiles " << (1 << level);
        // The same stencil resolved tile by tile inside the pass (what the techniques run):
        // a difference means a bin tile was resolved from a stale or partial stencil, or the
        // background / facing-away rule of resolveVisibility was not followed.
        const FacingAway away(scene, scene.lights[l], view);
        Image<float> expected_visibility, visibility;
        resolveVisibility(scene, scene.lights[l], view, eye, expected_visibility,
                          [&](int x, int y) { return stencil.at(x, y) != 0 ? 0.0f : 1.0f; });
        Stats fused_stats;
        tiledVolumeVisibility(volumes, eye, away, options, visibility, fused_stats);
        EXPECT_TRUE(visibility == expected_visibility)
            << what << ", light " << l << ", fused resolve, tiles " << (1 << level);
        EXPECT_TRUE(fused_stats.sameCounters(stats)) << what << ", light " << l;
      }
  }
}

// The thesis's 8x8 tiles and the technique's default, the bin tiles (hierarchical_technique.cpp).
// Release: about 0.9 s for every built-in scene at 96x64, both tile sizes.
TEST(HierarchicalVolume, SameStencilAsPerPixelOnEveryBuiltinScene) {
  for (const std::string& name : builtinSceneNames()) {
    const Scene scene = builtinScene(name);
    const View view = scene.camera.makeView(96, 64);
    for (VolumeMode mode : {VolumeMode::Auto, VolumeMode::ZPass, VolumeMode::ZFail})
      expectSameStencils(scene, view, mode, {3, kBinTileLevel}, name);
  }
}

// Tile sizes from 4x4 to the 32x32 bin tiles, on a scene with many volumes, larger than above so
// that tiles are decided whole at every size.
TEST(HierarchicalVolume, SameStencilAtEveryTileSize) {
  const Scene scene = builtinScene("columns");
  const View view = scene.camera.makeView(200, 134);
  for (VolumeMode mode : {VolumeMode::ZPass, VolumeMode::ZFail})
    expectSameStencils(scene, view, mode, {2, 3, 4, 5}, "columns");
}

// The eye inside the sphere's shadow volume: Auto and z-fail count from infinity; forced z-pass
// is wrong there, and the hierarchical volumes must be wrong in exactly the same way (its
// volume is open on screen: every tile drawn per pixel).
TEST(HierarchicalVolume, SameStencilWithTheEyeInsideAVolume) {
  const Scene scene = sphereOverGround(vec3(0.2f, 0.6f, 0.1f), vec3(4, 0, 3), vec3(0, 12, 0));
  const View view = scene.camera.makeView(96, 64);
  for (VolumeMode mode : {VolumeMode::Auto, VolumeMode::ZPass, VolumeMode::ZFail})
    expectSameStencils(scene, view, mode, {3, kBinTileLevel}, "eye inside");
}

// The light in the view frustum: volumes extrude away from a point on screen and reach
// infinity (depth 0) in every direction; a light inside the closed sphere shadows everything.
TEST(HierarchicalVolume, SameStencilWithTheLightInTheView) {
  const Scene in_view = sphereOverGround(vec3(6, 4, 6), vec3(0, 4, 0), vec3(-1, 5, -1));
  const Scene inside = sphereOverGround(vec3(5, 4, 6), vec3(0, 1, 0), vec3(0, 2, 0));
  for (VolumeMode mode : {VolumeMode::Auto, VolumeMode::ZPass, VolumeMode::ZFail}) {
    expectSameStencils(in_view, in_view.camera.makeView(96, 64), mode, {3, kBinTileLevel},
                       "light in view");
    expectSameStencils(inside, inside.camera.makeView(96, 64), mode, {3, kBinTileLevel},
                       "light inside");
  }
}

// The light below the ground: the ground faces away from it, so its pixels are 0 by the
// facing rule wherever the stencil is 0, and the sphere's volume reaches few of its tiles. Most
// bin tiles write no stencil there and are resolved after the tile pass, along the image's
// rows (tiledVolumeVisibility): a difference from the rule applied to the per-pixel stencil
// means that resolve lost the facing rule or a tile's place.
TEST(HierarchicalVolume, SameStencilWithTheLightBelowTheGround) {
  const Scene scene = sphereOverGround(vec3(4, 5, 6), vec3(0, 1, 0), vec3(1, -3, 2));
  for (VolumeMode mode : {VolumeMode::Auto, VolumeMode::ZPass, VolumeMode::ZFail})
    for (const auto& [w, h] : {std::pair{96, 64}, std::pair{200, 134}})
      expectSameStencils(scene, scene.camera.makeView(w, h), mode, {3, kBinTileLevel},
                         "light below the ground");
  // The case is the one described: the facing rule darkens most of the image.
  const View view = scene.camera.makeView(200, 134);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  const FacingAway away(scene, scene.lights[0], view);
  size_t facing_away = 0;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const uint32_t id = eye.primitive.at(x, y);
      facing_away += id != kNoPrimitive && away(id) ? 1 : 0;
    }
  EXPECT_GT(facing_away, size_t(view.width * view.height / 2));
}

// The eye in the plane of a shadow volume's face: a tetrahedron whose edge from (1, 2, -1) to
// (1, 2, 1) is a silhouette edge for the light at (1, 10, 0), so its quad lies in the plane
// x = 1, and the eye at x = 1 looking along it. The quad projects to the image's middle column
// and set-up drops it (ShadowVolumeSet::vanished); the shadow's edge runs along it, through
// the middle of tiles. If the dropped quad were not kept, no drawn triangle would cross those
// tiles' boxes and one sample would shadow or light each tile whole.
TEST(HierarchicalVolume, SameStencilWithAFaceSeenEdgeOn) {
  Scene scene;
  scene.name = "edge-on";
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeGroundPlane(vec3(0), 20.0f));
  Mesh tetra;
  tetra.name = "tetrahedron";
  tetra.positions = {{1, 2, -1}, {1, 2, 1}, {0, 3, 0}, {0, 1, 0}};
  tetra.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};  // counter-clockwise seen from outside
  scene.meshes.push_back(tetra);
  scene.lights.push_back(Light{vec3(1, 10, 0), 0.0f, vec3(1), 1.0f});
  scene.camera.position = vec3(1, 6, 6);
  scene.camera.target = vec3(1, 0.5f, 0);
  scene.camera.fov_y = 50.0f;
  scene.finalize();
  ASSERT_TRUE(scene.meshes[1].closed);
  // 100 pixels wide: the middle column, x = 50, is inside a 32x32 and an 8x8 tile.
  for (VolumeMode mode : {VolumeMode::ZPass, VolumeMode::ZFail})
    expectSameStencils(scene, scene.camera.makeView(100, 67), mode, {3, kBinTileLevel},
                       "edge-on");
  Stats eye_stats;
  const View view = scene.camera.makeView(100, 67);
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  Stats stats;
  const ShadowVolumeSet set =
      buildShadowVolumes(scene, scene.lights[0].center, view, eye, VolumeMode::ZPass, stats);
  EXPECT_GT(set.vanished_begin[2] - set.vanished_begin[1], 0u)
      << "the quad seen edge-on should have vanished in set-up";
}

// Through the technique API: the same visibility bits as `volume`, and counters that do not
// depend on the thread count or on SIMD vs scalar kernels.
TEST(HierarchicalVolume, TechniquesMatchVolumeAndCountersAreInvariant) {
  const Scene scene = builtinScene("spheres");
  const View view = scene.camera.makeView(96, 64);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  const TechniqueResult volume =
      renderShadows(TechniqueConfig("volume"), scene, scene.lights[0], view, eye);
  for (const char* name : {"hierarchical-volume", "depth-bounds-volume"}) {
    TechniqueResult base;
    {
      ThreadLimit limit(1);
      RenderContext scalar;
      scalar.simd = false;
      base = renderShadows(TechniqueConfig(name), scene, scene.lights[0], view, eye, scalar);
    }
    EXPECT_TRUE(base.visibility == volume.visibility) << name;
    EXPECT_GT(base.stats.pixels_rasterized, 0u) << name;
    for (int threads : {2, 3}) {
      ThreadLimit limit(threads);
      const TechniqueResult r =
          renderShadows(TechniqueConfig(name), scene, scene.lights[0], view, eye);
      EXPECT_TRUE(r.visibility == base.visibility) << name << ", " << threads << " threads";
      EXPECT_TRUE(r.stats.sameCounters(base.stats)) << name << ", " << threads << " threads";
    }
  }
}

// The shared models' scene files (skipped where the models are absent): real meshes, many
// volumes per tile, terminators on finely tessellated surfaces.
TEST(HierarchicalVolume, SameStencilOnModelScenes) {
  int ran = 0;
  for (const char* file : {"dragon-res2.json", "bunny-lowres.json"}) {
    const std::filesystem::path path =
        std::filesystem::path(PENUMBRA_SOURCE_DIR) / "scenes" / file;
    if (!sceneModelsPresent(path)) continue;
    const Scene scene = loadSceneFile(path.string());
    for (VolumeMode mode : {VolumeMode::ZPass, VolumeMode::ZFail})
      expectSameStencils(scene, scene.camera.makeView(160, 107), mode, {3, kBinTileLevel}, file);
    ++ran;
  }
  if (ran == 0) GTEST_SKIP() << "models of scenes/dragon-res2.json, bunny-lowres.json absent";
}

// --- The hand-made case. ---
//
// A 32x32 image (one bin tile, 4x4 tiles of 8x8) and one closed volume built directly in screen
// space: a box over pixels [8, 24) x [8, 24) (tiles (1,1), (2,1), (1,2), (2,2)) whose front face
// lies at depth 0.8 and back face at 0.2 (its sides are edge-on: no pixel). Each face is two
// triangles split along the diagonal from (8, 8) to (24, 24); the upper-right triangle comes
// first. Clip-space w = 1, so screen coordinates and depths are the given ones exactly. With
// `sides`, the four edge-on side faces are there too, two triangles each, as a real volume seen
// with the eye in their planes would have them: set-up drops them (ShadowVolumeSet::vanished).
struct HandCase {
  ShadowVolumeSet volumes;
  DepthBuffer depth;
};

HandCase handCase(bool zfail, float (*surface)(int x, int y), bool sides = false) {
  HandCase c;
  c.depth.depth.resize(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) c.depth.depth.at(x, y) = surface(x, y);
  c.depth.buildTileRanges();
  ClipTriangles tris;
  auto vertex = [&](float sx, float sy, float z) {
    return tris.addVertex(vec4(sx / 16.0f - 1.0f, 1.0f - sy / 16.0f, z, 1.0f));
  };
  const uint8_t flags = zfail ? kZFail : 0;
  for (float z : {0.8f, 0.2f}) {
    const uint32_t a = vertex(8, 8, z), b = vertex(24, 8, z), cc = vertex(24, 24, z),
                   d = vertex(8, 24, z);
    if (z > 0.5f) {  // front face, counter-clockwise as the eye sees it (y up in clip space)
      tris.add(a, cc, b, 1, flags);
      tris.add(a, d, cc, 1, flags);
    } else {  // back face
      tris.add(a, b, cc, 1, flags);
      tris.add(a, cc, d, 1, flags);
    }
  }
  if (sides) {
    const float corners[5][2] = {{8, 8}, {24, 8}, {24, 24}, {8, 24}, {8, 8}};
    for (int k = 0; k < 4; ++k) {
      const float* p = corners[k];
      const float* q = corners[k + 1];
      const uint32_t p0 = vertex(p[0], p[1], 0.8f), q0 = vertex(q[0], q[1], 0.8f);
      const uint32_t p1 = vertex(p[0], p[1], 0.2f), q1 = vertex(q[0], q[1], 0.2f);
      tris.add(p0, q0, q1, 1, flags);
      tris.add(p0, q1, p1, 1, flags);
    }
  }
  std::vector<VanishedPiece> vanished;
  c.volumes.triangles = setupTriangles(tris, 32, 32, nullptr, &vanished);
  c.volumes.begin = {0, uint32_t(c.volumes.triangles.size())};
  c.volumes.zfail = {uint8_t(zfail)};
  c.volumes.may_contain_eye = {0};
  c.volumes.depth_min = {0.2f};
  c.volumes.depth_max = {0.8f};
  EXPECT_EQ(vanished.size(), sides ? 8u : 0u) << "only the edge-on sides vanish";
  indexVanishedPieces(tris, std::move(vanished), c.volumes);
  return c;
}

Image<int32_t> runTiled(const HandCase& c, VolumeCulling culling, Stats& stats, bool simd) {
  TiledVolumeStencilOptions options;
  options.culling = culling;
  options.simd = simd;
  return tiledVolumeStencil(c.volumes, c.depth, options, stats);
}

Image<int32_t> runPerPixel(const HandCase& c, Stats& stats) {
  Image<int32_t> stencil(32, 32, 0);
  StencilOptions options;
  options.two_level = false;
  options.cull_level = 3;
  rasterizeStencil(c.volumes.triangles, c.depth, stencil, stats, options);
  return stencil;
}

// z-pass, surface at 0.5 except the column band x in [12, 16) at 0.1 (behind the back face).
// Tiles (1,1) and (1,2) hold depths 0.1..0.5: the back face (0.2) crosses their boxes, so they
// are boundary tiles; tiles (2,1), (2,2) (depth 0.5) lie between the faces: one sample sees the
// front face only, +1, shadowed.
//
// Tile tests: each triangle is first tested against the box of its whole rect (its 2x2 tiles)
// and the bin tile's depth range 0.1..0.5: the front triangles are in front of it (1 test each,
// no tile tested alone); the back ones cross it, so their tiles are tested one by one, in the
// order (1,1), (2,1), (1,2), (2,2): the upper-right one marks (1,1) boundary, finds (2,1) and
// (2,2) behind and misses (1,2) (1 + 4 tests, 1 culled); the lower-left one skips (1,1),
// boundary already, misses (2,1), marks (1,2) boundary and finds (2,2) behind (1 + 3 tests,
// 1 culled). Then the per-pixel part walks each triangle's 4 tiles (16 tests), culling the 2
// that are not boundary tiles (8 culled).
//
// Per pixel in the boundary tiles: the lower-left front triangle covers all of tile (1,2) and
// is in front of every depth there: taken whole (1 accepted tile, 1 per-tile write); the front
// face's two triangles share tile (1,1): 64 pixels, all written; the back face covers both
// tiles, 128 pixels, in front only of the band (4 x 16 = 64 writes). 192 pixels and z reads,
// 128 kernel writes. Per-tile counts: 2 written for the shadowed tiles, then added to the
// surface pixels of the three tiles with a non-zero count: 3 x 64.
float bandSurface(int x, int) { return x >= 12 && x < 16 ? 0.1f : 0.5f; }

TEST(HierarchicalVolume, HandMadeCountersZPass) {
  const HandCase c = handCase(false, bandSurface);
  ASSERT_EQ(c.volumes.triangles.size(), 4u);
  EXPECT_EQ(c.volumes.triangles[0].facing, 1) << "the front face must face the eye";
  EXPECT_EQ(c.volumes.triangles[2].facing, -1);
  Stats per_pixel_stats;
  const Image<int32_t> expected = runPerPixel(c, per_pixel_stats);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool in_box = x >= 8 && x < 24 && y >= 8 && y < 24;
      ASSERT_EQ(expected.at(x, y), in_box && !(x >= 12 && x < 16) ? 1 : 0) << x << "," << y;
    }
  for (bool simd : {false, true}) {
    if (simd && !simdKernelsAvailable()) continue;
    Stats s;
    const Image<int32_t> stencil = runTiled(c, VolumeCulling::Hierarchical, s, simd);
    EXPECT_TRUE(stencil == expected);
    EXPECT_EQ(s.counter("tiles_boundary"), 2u);
    EXPECT_EQ(s.counter("tiles_shadowed"), 2u);
    EXPECT_EQ(s.counter("tiles_lit"), 0u);
    EXPECT_EQ(s.tiles_accepted, 1u);
    EXPECT_EQ(s.pixels_rasterized, 192u);
    EXPECT_EQ(s.z_reads, 192u);
    EXPECT_EQ(s.stencil_writes, 128u + 1u + 2u + 3u * 64u);
    EXPECT_EQ(s.tiles_tested, 11u + 16u);
    EXPECT_EQ(s.tiles_culled, 2u + 8u);
  }
  // Per pixel (8x8 culling tiles): both front triangles everywhere (256 pixels, all written);
  // the back face only where a tile's z-min lies behind it, tiles (1,1), (1,2): 128 pixels,
  // 64 written. Depth bounds [0.2, 0.8] reject no tile here: the same numbers.
  EXPECT_EQ(per_pixel_stats.pixels_rasterized, 384u);
  EXPECT_EQ(per_pixel_stats.stencil_writes, 320u);
  Stats bounds;
  EXPECT_TRUE(runTiled(c, VolumeCulling::DepthBounds, bounds, true) == expected);
  EXPECT_EQ(bounds.pixels_rasterized, 384u);
  EXPECT_EQ(bounds.z_reads, 384u);
  EXPECT_EQ(bounds.stencil_writes, 320u);
}

// z-fail with every surface at 0.9, nearer than the whole volume: each pixel's count is the
// closed volume's sum, zero. Depth bounds (0.2..0.8) reject all four tiles: no pixel. Per pixel,
// every polygon is behind every surface, so no tile is culled: 4 x 128 = 512 pixels, all written.
// Hierarchical: the same depth bounds test, on the bin tile's range, rejects the volume whole.
TEST(HierarchicalVolume, HandMadeCountersZFailNearSurface) {
  const HandCase c = handCase(true, [](int, int) { return 0.9f; });
  Stats per_pixel_stats;
  const Image<int32_t> expected = runPerPixel(c, per_pixel_stats);
  EXPECT_TRUE(expected == Image<int32_t>(32, 32, 0));
  EXPECT_EQ(per_pixel_stats.pixels_rasterized, 512u);
  EXPECT_EQ(per_pixel_stats.stencil_writes, 512u);
  Stats bounds;
  EXPECT_TRUE(runTiled(c, VolumeCulling::DepthBounds, bounds, true) == expected);
  EXPECT_EQ(bounds.pixels_rasterized, 0u);
  EXPECT_EQ(bounds.stencil_writes, 0u);
  Stats h;
  EXPECT_TRUE(runTiled(c, VolumeCulling::Hierarchical, h, true) == expected);
  EXPECT_EQ(h.tiles_tested + h.counter("tiles_lit") + h.counter("tiles_shadowed") +
                h.counter("tiles_boundary"),
            0u)
      << "the bin tile's range lies nearer than the volume: nothing to classify";
  EXPECT_EQ(h.pixels_rasterized + h.z_reads + h.stencil_writes, 0u);
  // Where the eye may be inside the volume, that rejection is not allowed: the tiles are
  // classified, both faces behind every box, and the sample sees +1 and -1: four lit tiles.
  HandCase eye_inside = c;
  eye_inside.volumes.may_contain_eye = {1};
  Stats e;
  EXPECT_TRUE(runTiled(eye_inside, VolumeCulling::Hierarchical, e, true) == expected);
  EXPECT_EQ(e.counter("tiles_lit"), 4u);
  EXPECT_EQ(e.counter("tiles_shadowed") + e.counter("tiles_boundary"), 0u);
  EXPECT_EQ(e.pixels_rasterized + e.z_reads + e.stencil_writes, 0u);
  // Depth bounds without their near test: every tile drawn per pixel, as the per-pixel pass.
  Stats b;
  EXPECT_TRUE(runTiled(eye_inside, VolumeCulling::DepthBounds, b, true) == expected);
  EXPECT_EQ(b.pixels_rasterized, 512u);
}

// z-pass, the closed box with its edge-on sides, surface at 0.5 between the faces, except
// background (depth 0, infinity) at pixels (8..9, 8) and (8..11, 9) in tile (1,1).
//
// No drawn triangle crosses any tile's box (front face in front, back face behind), so the
// thesis's test alone would decide the whole bin tile by one sample, its first surface pixel
// (0, 0), outside the box: all lit, against 1 inside the box per pixel. The sides, dropped by
// set-up, reach every tile from (0,0) to (3,3) (their pixel boxes take a pixel of margin): the
// four tiles the faces' rects reach are boundary tiles, and with no tile decided each triangle
// is drawn over its whole rect after one depth test on the bin tile's range: the back face is
// culled (behind every depth), the front face's two triangles cover 256 pixels. Tile (1,1)'s
// stored range reaches 0, and every volume extruded away from the light reaches infinity: its
// box is taken over its 58 surface pixels instead, at the cost of reading its 64 depths. Wrong
// if a tile was decided by a sample, if the background stretched a box, or if a background
// pixel took a count.
float backgroundInATile(int x, int y) {
  return (y == 8 && x >= 8 && x < 10) || (y == 9 && x >= 8 && x < 12) ? 0.0f : 0.5f;
}

TEST(HierarchicalVolume, HandMadeEdgeOnSidesAndBackground) {
  const HandCase c = handCase(false, backgroundInATile, true);
  Stats per_pixel_stats;
  const Image<int32_t> expected = runPerPixel(c, per_pixel_stats);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool in_box = x >= 8 && x < 24 && y >= 8 && y < 24;
      ASSERT_EQ(expected.at(x, y), in_box && backgroundInATile(x, y) > 0.0f ? 1 : 0)
          << x << "," << y;
    }
  for (bool simd : {false, true}) {
    if (simd && !simdKernelsAvailable()) continue;
    Stats s;
    EXPECT_TRUE(runTiled(c, VolumeCulling::Hierarchical, s, simd) == expected);
    EXPECT_EQ(s.counter("tiles_boundary"), 4u);
    EXPECT_EQ(s.counter("tiles_lit") + s.counter("tiles_shadowed"), 0u);
    EXPECT_EQ(s.tiles_accepted, 0u);
    EXPECT_EQ(s.pixels_rasterized, 256u);
    EXPECT_EQ(s.z_reads, 256u + 64u);
  }
  // Without the sides the volume is not closed on screen, and the one sample decides: the
  // reason the dropped faces are kept.
  const HandCase open = handCase(false, backgroundInATile, false);
  Stats s;
  EXPECT_TRUE(runTiled(open, VolumeCulling::Hierarchical, s, true) == Image<int32_t>(32, 32, 0));
  EXPECT_EQ(s.counter("tiles_lit"), 4u);
}

}  // namespace test_hierarchical_volume
}  // namespace penumbra

namespace penumbra {
namespace test_hierarchical_volume {

// A z-pass volume has no light caps, so across a silhouette edge the drawn count changes even
// where the quad lies wholly in front of the tile's surfaces: a tile such an edge crosses is a
// boundary tile. Here a single quad (as if the rest of its volume lay off screen) at depth 0.8,
// over a surface at 0.5, spans pixels [12, 24) x [8, 16); its left edge, x = 12, is a silhouette
// edge and crosses tile (1,1) (columns 8..15); its other edges lie on tile borders. Per pixel,
// columns 12..15 of tile (1,1) count +1 and columns 8..11 do not; decided by its sample (8, 8),
// which the quad does not cover, the whole tile would come out lit.
TEST(HierarchicalVolume, SilhouetteEdgeMakesABoundaryTile) {
  HandCase c;
  c.depth.depth.resize(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) c.depth.depth.at(x, y) = 0.5f;
  c.depth.buildTileRanges();
  ClipTriangles tris;
  auto vertex = [&](float sx, float sy) {
    return tris.addVertex(vec4(sx / 16.0f - 1.0f, 1.0f - sy / 16.0f, 0.8f, 1.0f));
  };
  const uint32_t a = vertex(12, 8), b = vertex(12, 16), cc = vertex(24, 16), d = vertex(24, 8);
  // Counter-clockwise as the eye sees them (y up in clip space); the first holds the edge a-b.
  tris.addOwned(a, b, cc, 1, 0, /*silhouette*/ 0, ClipTriangles::kNoOwner);
  tris.add(a, cc, d, 1, 0);
  c.volumes.triangles = setupTriangles(tris, 32, 32);
  ASSERT_EQ(c.volumes.triangles.size(), 2u);
  ASSERT_EQ(c.volumes.triangles[0].facing, 1);
  c.volumes.begin = {0, 2};
  c.volumes.zfail = {0};
  c.volumes.may_contain_eye = {0};
  c.volumes.depth_min = {0.8f};
  c.volumes.depth_max = {0.8f};
  c.volumes.silhouettes = {ScreenSegment{12.0, 8.0, 12.0, 16.0, false}};
  Stats per_pixel_stats;
  const Image<int32_t> expected = runPerPixel(c, per_pixel_stats);
  ASSERT_EQ(expected.at(11, 10), 0);
  ASSERT_EQ(expected.at(12, 10), 1);
  TiledVolumeStencilOptions options;
  options.dense_limit = 0;
  Stats s;
  EXPECT_TRUE(tiledVolumeStencil(c.volumes, c.depth, options, s) == expected);
  EXPECT_EQ(s.counter("tiles_boundary"), 1u) << "tile (1,1)";
  EXPECT_EQ(s.counter("tiles_shadowed"), 1u) << "tile (2,1)";
}

}  // namespace test_hierarchical_volume
}  // namespace penumbra
