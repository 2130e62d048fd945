// Caster culling (src/shadows/stages/caster_culling/, docs/caster-culling.md) leaves out the
// casters whose shadow reaches no visible point. It must be invisible: every technique built on
// the shared volume stages renders bit-identical frames with it on and off, on every built-in
// scene, the large ones at small sizes and frames of their walkthroughs; and it must
// do something: casters are culled on those scenes, an off-screen caster whose shadow does fall
// on screen is kept, and so is a caster whose box holds the light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/frame.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/path.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"

namespace penumbra {
namespace test_caster_culling {

// Every technique that goes through the shared silhouette, volume, potential-edge or stencil
// stages (the shadow maps, the oracle and alias-free do not), and the options that change which
// volumes are drawn: z-pass forced (a volume holding the eye counts at every pixel, so such a
// caster must never be culled), z-fail forced, and the masks' own low-resolution depth pass.
struct CullingCase {
  std::string technique;
  std::vector<std::pair<std::string, std::string>> options{};
};
const std::vector<CullingCase> kCullingCases = {
    {"volume"},
    {"volume", {{"volume-mode", "zpass"}}},
    {"volume", {{"volume-mode", "zfail"}}},
    {"hierarchical-volume"},
    {"depth-bounds-volume"},
    {"wedge-2002"},
    {"wedge-3pass"},
    {"wedge-1pass", {{"volume-mode", "zfail"}}},
    {"coverage"},
    {"exact"},
    {"heckbert-herf"},
    {"mask-alpha"},
    {"mask-colour", {{"mask-scale", "2"}}}};

FrameResult render(const Scene& scene, const CullingCase& technique, bool culling, int width,
                   int height) {
  FrameOptions options;
  options.technique = TechniqueConfig(technique.technique);
  for (const auto& [option, value] : technique.options) options.technique.set(option, value);
  options.width = width;
  options.height = height;
  options.context.caster_culling = culling ? CasterCullingMode::On : CasterCullingMode::Off;
  return renderFrame(scene, options);
}

// Empty images (a light's per-channel visibility when it has no texture) are equal; memcmp
// may not be given their null data.
bool sameBits(const Image<float>& a, const Image<float>& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

uint64_t culledCasters(const FrameResult& frame) {
  uint64_t culled = 0;
  for (const TechniqueResult& light : frame.lights) culled += light.stats.counter("casters_culled");
  return culled;
}

// Renders `scene` with every culling technique, on and off; returns the casters culled (summed
// over techniques and lights) so a caller can check the comparison was not vacuous.
uint64_t expectSameFrames(const Scene& scene, const std::string& what, int width = 96,
                          int height = 64) {
  uint64_t culled = 0;
  for (const CullingCase& culling_case : kCullingCases) {
    std::string technique = culling_case.technique;
    for (const auto& [option, value] : culling_case.options)
      technique += " --" + option + " " + value;
    FrameResult off, on;
    try {
      off = render(scene, culling_case, false, width, height);
    } catch (const Error&) {
      // A technique that refuses the scene (the wedges take only spherical lights) must refuse
      // it the same way with culling on.
      EXPECT_THROW(render(scene, culling_case, true, width, height), Error)
          << what << ", " << technique;
      continue;
    }
    on = render(scene, culling_case, true, width, height);
    EXPECT_EQ(on.lights.size(), off.lights.size()) << what << ", " << technique;
    if (on.lights.size() != off.lights.size()) continue;
    for (size_t l = 0; l < on.lights.size(); ++l) {
      // A difference means a culled caster did contribute at some visible point: the culling
      // test is not conservative for this technique.
      EXPECT_TRUE(sameBits(on.lights[l].visibility, off.lights[l].visibility))
          << what << ", " << technique << ", light " << l << ": visibility differs";
      for (size_t c = 0; c < 3; ++c)
        EXPECT_TRUE(sameBits(on.lights[l].channels[c], off.lights[l].channels[c]))
            << what << ", " << technique << ", light " << l << ": channel " << c;
      // Off, nothing is tested or counted.
      EXPECT_EQ(off.lights[l].stats.counter("casters_tested"), 0u) << what << ", " << technique;
      EXPECT_EQ(on.lights[l].stats.counter("casters_tested"), scene.meshes.size())
          << what << ", " << technique;
    }
    culled += culledCasters(on);
  }
  return culled;
}

TEST(CasterCulling, SameFramesOnSmallBuiltinScenes) {
  for (const std::string& name : builtinSceneNames()) expectSameFrames(builtinScene(name), name);
}

// The instance scenes, where culling pays: many meshes, many of them behind the camera or
// shadowing ground nobody sees. Their walkthroughs put the camera among them (frame 60 of the
// city's, at street level; 30 of the interior's). interior:1 is one bay, every lamp and
// column in view: nothing to cull, so the interior is taken at 2 x 2 bays.
TEST(CasterCulling, SameFramesOnCityAndInterior) {
  for (const auto& [name, frames] :
       std::vector<std::pair<std::string, std::vector<int>>>{{"city:1", {60}},
                                                             {"interior:2", {30}}}) {
    Scene scene = builtinScene(name);
    EXPECT_GT(expectSameFrames(scene, name), 0u) << name << ": nothing was culled";
    for (const int frame : frames) {
      applyPathFrame(scene, frame);
      const std::string what = name + " path frame " + std::to_string(frame);
      EXPECT_GT(expectSameFrames(scene, what), 0u) << what << ": nothing was culled";
    }
  }
}

// A ground plane seen from above, a point light over it, and boxes around: `casters` are added
// by each test.
Scene groundScene(const vec3& light, float radius) {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeGroundPlane(vec3(0), 4.0f));
  scene.lights.push_back(Light{light, radius, vec3(1), 1.0f});
  scene.camera.position = vec3(0.0f, 6.0f, 0.01f);
  scene.camera.target = vec3(0.0f);
  scene.camera.fov_y = 40.0f;
  return scene;
}

// A box far out on the side away from the light, beyond the view: its shadow falls farther out
// still, on ground nobody sees, so it is culled (by every technique) and the image is the same.
TEST(CasterCulling, CasterWhoseShadowIsOffScreenIsCulled) {
  Scene scene = groundScene(vec3(0.0f, 5.0f, 0.0f), 0.2f);
  scene.meshes.push_back(makeBox(vec3(30.0f, 0.0f, -1.0f), vec3(31.0f, 1.0f, 1.0f)));
  scene.finalize();
  for (const char* technique : {"volume", "exact", "hierarchical-volume"}) {
    const FrameResult on = render(scene, CullingCase{technique}, true, 64, 64);
    EXPECT_EQ(on.lights[0].stats.counter("casters_culled"), 1u) << technique;
    EXPECT_GT(on.lights[0].stats.counter("culled_caster_edges"), 0u) << technique;
  }
  expectSameFrames(scene, "off-screen box, shadow off-screen", 64, 64);
}

// A box above the camera, out of its view (the camera looks straight down from below it), with
// the light above the box: its shadow falls on the visible ground. It must be kept, and the
// image must show its shadow.
TEST(CasterCulling, OffScreenCasterShadowingVisibleGroundIsKept) {
  Scene scene = groundScene(vec3(0.2f, 12.0f, 0.1f), 0.3f);
  scene.meshes.push_back(makeBox(vec3(-1.0f, 8.0f, -1.0f), vec3(1.0f, 8.5f, 1.0f)));
  scene.finalize();
  for (const char* technique : {"volume", "exact", "wedge-3pass", "coverage"}) {
    const FrameResult on = render(scene, CullingCase{technique}, true, 64, 64);
    EXPECT_EQ(on.lights[0].stats.counter("casters_culled"), 0u) << technique;
    // The box is not on screen: no visible pixel is one of its triangles.
    const uint32_t first_box = scene.triangle_offsets[1];
    float darkest = 1.0f;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        EXPECT_LT(on.eye.primitive.at(x, y), first_box);
        darkest = std::min(darkest, on.lights[0].visibility.at(x, y));
      }
    EXPECT_EQ(darkest, 0.0f) << technique << ": the box's umbra should reach the ground";
  }
  expectSameFrames(scene, "off-screen box shadowing the ground", 64, 64);
}

// A light inside a caster's box (a room around it, open at the bottom: a lampshade over the
// ground): the caster is never culled, whatever the receivers.
TEST(CasterCulling, CasterHoldingTheLightIsKept) {
  Scene scene = groundScene(vec3(0.0f, 2.0f, 0.0f), 0.1f);
  Mesh shade = makeBox(vec3(-0.5f, 1.5f, -0.5f), vec3(0.5f, 2.5f, 0.5f));
  // Leave out the two bottom triangles (those facing -y): light leaves through the opening.
  Mesh open;
  open.positions = shade.positions;
  for (size_t t = 0; t < shade.triangleCount(); ++t) {
    const vec3 a = shade.vertex(t, 0), b = shade.vertex(t, 1), c = shade.vertex(t, 2);
    if (a.y == 1.5f && b.y == 1.5f && c.y == 1.5f) continue;
    open.indices.insert(open.indices.end(), shade.indices.begin() + long(3 * t),
                        shade.indices.begin() + long(3 * t + 3));
  }
  open.corner_normals.assign(open.indices.size(), vec3(0, 1, 0));
  scene.meshes.push_back(open);
  scene.finalize();
  for (const char* technique : {"volume", "exact", "coverage"}) {
    const FrameResult on = render(scene, CullingCase{technique}, true, 64, 64);
    EXPECT_EQ(on.lights[0].stats.counter("casters_culled"), 0u) << technique;
  }
  expectSameFrames(scene, "light inside a caster's box", 64, 64);
}

// Auto culls where the scene has at least as many edges as the frame has pixels, and nowhere
// else: if this failed, the default would pay the receiver mask on small scenes at large frames
// (measured slower: docs/caster-culling.md) or skip culling on the scenes it is for.
TEST(CasterCulling, AutoCullsWhereEdgesOutnumberThePixels) {
  Scene scene = groundScene(vec3(0.0f, 5.0f, 0.0f), 0.2f);
  scene.finalize();
  size_t edges = 0;
  for (const EdgeAdjacency& adjacency : scene.adjacency) edges += adjacency.edges.size();
  View small, large;
  small.width = 1;
  small.height = int(edges);  // exactly as many pixels as edges: culled
  large.width = 1;
  large.height = int(edges) + 1;
  EXPECT_TRUE(castersCulled(CasterCullingMode::Auto, scene, small));
  EXPECT_FALSE(castersCulled(CasterCullingMode::Auto, scene, large));
  EXPECT_TRUE(castersCulled(CasterCullingMode::On, scene, large));
  EXPECT_FALSE(castersCulled(CasterCullingMode::Off, scene, small));
  EXPECT_EQ(parseCasterCulling("auto"), CasterCullingMode::Auto);
  EXPECT_THROW(parseCasterCulling("yes"), Error);
}

}  // namespace test_caster_culling
}  // namespace penumbra
