// Object-level occlusion culling in the eye pass (raster/occlusion_culler.h,
// docs/occlusion-culling.md): frames are bit-identical with it on and off, it culls hidden
// objects, and it never culls an object whose box holds the eye or reaches the near plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "raster/eye_pass.h"
#include "raster/occlusion_culler.h"
#include "render/frame.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/normals.h"
#include "scene/path.h"

namespace penumbra::testing {
namespace test_occlusion_culling {

constexpr int kWidth = 192;
constexpr int kHeight = 108;

template <class T>
bool sameImage(const Image<T>& a, const Image<T>& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0) return false;
  return true;
}

// Every buffer the eye pass hands the techniques, bit for bit.
void expectSameEye(const EyeBuffers& culled, const EyeBuffers& all, const std::string& where) {
  EXPECT_TRUE(sameImage(culled.depth.depth, all.depth.depth)) << where << ": depth differs";
  EXPECT_TRUE(sameImage(culled.primitive, all.primitive)) << where << ": primitive ids differ";
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    EXPECT_TRUE(sameImage(culled.depth.tiles[level].zmin, all.depth.tiles[level].zmin))
        << where << ": tile z-min differs at level " << level;
    EXPECT_TRUE(sameImage(culled.depth.tiles[level].zmax, all.depth.tiles[level].zmax))
        << where << ": tile z-max differs at level " << level;
  }
  EXPECT_EQ(culled.mesh_vertex_base, all.mesh_vertex_base) << where;
  ASSERT_EQ(culled.clip_vertices.size(), all.clip_vertices.size()) << where;
  EXPECT_EQ(0, std::memcmp(culled.clip_vertices.data(), all.clip_vertices.data(),
                           all.clip_vertices.size() * sizeof(vec4)))
      << where << ": clip-space vertices differ (shadow volumes' light caps read them)";
}

FrameResult render(const Scene& scene, const std::string& technique, bool culling) {
  FrameOptions options;
  options.technique = TechniqueConfig(technique);
  options.width = kWidth;
  options.height = kHeight;
  options.occlusion_culling = culling ? OcclusionCullingMode::On : OcclusionCullingMode::Off;
  return renderFrame(scene, options);
}

void expectSameFrame(const Scene& scene, const std::string& technique, const std::string& where) {
  const FrameResult on = render(scene, technique, true);
  const FrameResult off = render(scene, technique, false);
  const std::string at = where + ", " + technique;
  expectSameEye(on.eye, off.eye, at);
  EXPECT_TRUE(sameImage(on.color, off.color)) << at << ": colour differs";
  ASSERT_EQ(on.lights.size(), off.lights.size());
  for (size_t i = 0; i < on.lights.size(); ++i)
    EXPECT_TRUE(sameImage(on.lights[i].visibility, off.lights[i].visibility))
        << at << ": visibility of light " << i << " differs";
  EXPECT_EQ(on.eye_stats.counter("occlusion_scene_triangles"), scene.triangleCount()) << at;
}

// A wrong cull would drop a surface that wins pixels: depth, ids and then every technique's
// visibility would change. Built-in city and interior, their default views and path frames.
TEST(OcclusionCulling, FramesAreBitIdenticalOnAndOff) {
  for (const char* name : {"city:1", "interior:1"}) {
    Scene scene = builtinScene(name);
    expectSameFrame(scene, "volume", name);
    expectSameFrame(scene, "shadow-map", name);
    ASSERT_GT(scene.path.frames, 4) << name << " should have a camera path";
    for (int frame : {1, scene.path.frames / 2}) {
      applyPathFrame(scene, frame);
      expectSameFrame(scene, "volume", std::string(name) + " frame " + std::to_string(frame));
    }
  }
}

// One culler along a path: each frame's first occluders are the last frame's visible objects,
// and each object's cached point is queried first. A stale choice must never cost a pixel.
TEST(OcclusionCulling, TrackedAcrossPathFramesStaysExact) {
  Scene scene = builtinScene("city:1");
  OcclusionCuller culler(scene);
  uint64_t culled = 0, point_hits = 0;
  for (int frame = 0; frame < scene.path.frames; frame += std::max(1, scene.path.frames / 6)) {
    applyPathFrame(scene, frame);
    const View view = scene.camera.makeView(kWidth, kHeight);
    for (bool simd : {true, false}) {
      Stats on_stats, off_stats;
      const EyeBuffers on = renderEyePass(scene, view, on_stats, simd, &culler);
      const EyeBuffers off = renderEyePass(scene, view, off_stats, simd);
      expectSameEye(on, off, "city:1 frame " + std::to_string(frame) + (simd ? "" : " scalar"));
      culled += on_stats.counter("occlusion_clusters_culled");
      point_hits += on_stats.counter("occlusion_point_hits");
    }
  }
  EXPECT_GT(culled, 0u) << "a city walk should hide some buildings";
  EXPECT_GT(point_hits, 0u) << "visible point tracking never found an object visible";
}

// A wall, a box hidden behind it, a pole through the near plane, a mesh whose box holds the eye
// and a box behind the eye.
Scene hostileScene() {
  Scene s;
  s.name = "occlusion-hostile";
  s.materials.push_back(Material{});
  auto add = [&](Mesh mesh, const char* name) {
    mesh.name = name;
    computeCornerNormals(mesh);
    s.meshes.push_back(std::move(mesh));
  };
  add(makeBox(vec3(-20.0f, -20.0f, -0.2f), vec3(20.0f, 20.0f, 0.0f)), "wall");
  add(makeBox(vec3(-1.0f, -1.0f, -4.0f), vec3(1.0f, 1.0f, -2.0f)), "hidden box");
  // From behind the eye to behind the wall: crosses the near plane.
  add(makeBox(vec3(0.5f, -0.05f, -3.0f), vec3(0.6f, 0.05f, 12.0f)), "pole");
  // A mesh whose box holds the eye, its two triangles far apart: one behind the eye, one behind
  // the wall, so every pixel it could cover is hidden or off screen and only its box says
  // "maybe visible".
  Mesh split;
  split.positions = {vec3(-0.5f, 0.0f, 11.0f), vec3(0.5f, 0.0f, 11.0f), vec3(0.0f, 0.5f, 11.0f),
                     vec3(-0.5f, 0.0f, -3.0f), vec3(0.5f, 0.0f, -3.0f), vec3(0.0f, 0.5f, -3.0f)};
  split.indices = {0, 1, 2, 3, 4, 5};
  add(std::move(split), "around the eye");
  add(makeBox(vec3(-1.0f, -1.0f, 10.0f), vec3(1.0f, 1.0f, 11.0f)), "behind the eye");
  s.lights.push_back(Light{vec3(3.0f, 6.0f, 9.0f), 0.0f, vec3(1.0f), 1.0f});
  s.camera.position = vec3(0.0f, 0.0f, 8.0f);
  s.camera.target = vec3(0.0f, 0.0f, 0.0f);
  s.finalize();
  return s;
}

TEST(OcclusionCulling, CullsHiddenBoxNeverAnEyeOrNearPlaneBox) {
  const Scene scene = hostileScene();
  const View view = scene.camera.makeView(kWidth, kHeight);
  OcclusionCuller culler(scene);
  ASSERT_EQ(culler.hierarchy().clusters.size(), 5u) << "each small mesh is one object";
  for (int frame = 0; frame < 2; ++frame) {  // cold, then with the last frame's visible objects
    Stats on_stats, off_stats;
    const EyeBuffers on = renderEyePass(scene, view, on_stats, true, &culler);
    const EyeBuffers off = renderEyePass(scene, view, off_stats, true);
    expectSameEye(on, off, "hostile frame " + std::to_string(frame));
    // Only the hidden box and the box behind the eye (12 triangles each) may go: the wall is
    // seen, the pole and the split mesh cross the near plane or hold the eye, which the box
    // query cannot bound.
    EXPECT_EQ(on_stats.counter("occlusion_clusters_culled"), 2u) << "frame " << frame;
    EXPECT_EQ(on_stats.counter("occlusion_submitted_triangles"), scene.triangleCount() - 24)
        << "frame " << frame;
  }
}

// Off: the renderer makes no culler and the eye pass reports none of its counters.
TEST(OcclusionCulling, OffReportsNoCullingCounters) {
  const Scene scene = hostileScene();
  const FrameResult off = render(scene, "volume", false);
  EXPECT_EQ(off.eye_stats.counter("occlusion_scene_triangles"), 0u);
  EXPECT_EQ(off.eye_stats.triangles, render(scene, "volume", true).eye_stats.triangles + 12)
      << "on, the hidden box's 12 triangles are not set up (those behind the eye never are)";
}

}  // namespace test_occlusion_culling
}  // namespace penumbra::testing
