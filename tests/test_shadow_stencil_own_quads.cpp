// The two-sided stencil exact counts from (shadow_stencil.h, skip_own_quads) where the answer is
// known without rays: nothing lies between a lone floor and the light, so D(c) is 0 on every
// floor pixel. The quads of the floor's border edges leave the surface along the very edge the
// border pixels lie beside: with the float depth test alone some of them are counted there, and
// the exact soft shadows along the border go black against the oracle.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "eye_frame_util.h"
#include "scene/generators.h"
#include "scene/scene_builder.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace test_shadow_stencil_own_quads {

// Pixels showing a triangle of mesh `checked_mesh` with the eye and the light centre strictly on
// the same side of its plane whose stencil is not 0, with and without skipping the own quads.
struct Miscounts {
  int with_skip = 0, without_skip = 0, checked = 0;
};

Miscounts miscounted(Scene scene, uint32_t checked_mesh, int width, int height) {
  const testing::EyeFrame f = testing::makeEyeFrame(std::move(scene), width, height);
  const dvec3 eye(f.view.eye), centre(f.scene.lights[0].center);
  Miscounts m;
  Image<int32_t> stencils[2];
  for (int skip = 0; skip < 2; ++skip) {
    ShadowStencilOptions options;
    options.policy = CasterPolicy::TwoSided;
    options.skip_own_quads = skip == 1;
    Stats stats;
    stencils[skip] =
        shadowStencil(f.scene, f.scene.lights[0].center, f.view, f.eye, options, stats);
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint32_t id = f.eye.primitive.at(x, y);
      if (id == kNoPrimitive) continue;
      const auto [mesh, triangle] = f.scene.locateTriangle(id);
      if (mesh != checked_mesh) continue;
      const Mesh& mm = f.scene.meshes[mesh];
      const dvec3 a(mm.vertex(triangle, 0)), b(mm.vertex(triangle, 1)), c(mm.vertex(triangle, 2));
      const dvec3 n = glm::cross(b - a, c - a);
      const double e = glm::dot(n, eye - a), l = glm::dot(n, centre - a);
      if (!((e > 0 && l > 0) || (e < 0 && l < 0))) continue;
      ++m.checked;
      m.without_skip += stencils[0].at(x, y) != 0;
      m.with_skip += stencils[1].at(x, y) != 0;
    }
  }
  return m;
}

void report(const char* what, const Miscounts& m) {
  std::printf("[ own quads] %s: %d pixels checked, D(c) != 0 on %d with the depth test alone, "
              "%d with own quads skipped\n",
              what, m.checked, m.without_skip, m.with_skip);
}

// A floor seen out to its far border at a grazing angle (the camera and light of
// scenes/dragon-res2.json): the border's quads hang from the edge the floor pixels lie beside.
TEST(ShadowStencilOwnQuads, LoneFloorCountsNothingUpToItsBorder) {
  Scene scene;
  scene.name = "lone-floor";
  const uint32_t material = addMaterial(scene, "grey", vec3(0.7f));
  addMesh(scene, makeGroundPlane(vec3(0.0f, -0.004f, 0.0f), 15.0f), material);
  addLight(scene, vec3(-2.2f, 4.21f, 2.8f), 0.25f);
  scene.camera.position = vec3(2.7f, 2.27f, 3.9f);
  scene.camera.target = vec3(0.1f, 0.59f, -0.2f);
  scene.camera.fov_y = 40.0f;
  scene.finalize();
  const Miscounts m = miscounted(std::move(scene), 0, 640, 427);
  report("lone floor", m);
  EXPECT_GT(m.checked, 100000);
  EXPECT_EQ(m.with_skip, 0);
}

}  // namespace test_shadow_stencil_own_quads
}  // namespace penumbra
