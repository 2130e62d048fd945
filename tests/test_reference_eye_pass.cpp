// The oracle on depth buffers from the real eye pass (rasterizer snapping, float depth), where
// ray origins are only approximately on their surfaces: no shadow acne, no light leaks.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/eye_pass.h"
#include "scene/generators.h"
#include "shadows/reference/reference_technique.h"
#include "test_reference_fixture.h"

namespace penumbra {
namespace test_reference_eye_pass {

Scene finalized(std::vector<Mesh> meshes, const Light& light) {
  Scene scene;
  scene.name = "reference eye-pass test";
  scene.meshes = std::move(meshes);
  scene.materials.emplace_back();
  scene.lights.push_back(light);
  scene.finalize();
  return scene;
}

using reference_test::renderReference;

TechniqueConfig hardOptions() { return reference_test::referenceConfig(256, 1, true); }

// A lone convex polyhedron: a point on a face the light is in front of sees the light (the
// body lies behind that face's plane); a point on a face turned away does not, however close
// to the terminator and to the face's edges. If this failed with lit faces reading 0, the ray
// offset is too small for the eye pass's depth errors (acne); with dark faces reading 1, rays
// start on the wrong side or slip past the edge of their own triangle.
TEST(ReferenceEyePass, ConvexSphereShadowsExactlyItsBackFaces) {
  Light light;
  light.center = vec3(4.0f, 3.0f, 1.0f);
  const Scene scene = finalized({makeSphere(vec3(0.0f), 1.0f, 48, 24)}, light);
  const View view = View::lookAt(200, 150, vec3(0.5f, 1.0f, 3.5f), vec3(0.0f), vec3(0, 1, 0),
                                 45.0f, 0.1f);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  const TechniqueResult result = renderReference(hardOptions(), scene, light, view, eye);
  int lit = 0, dark = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      const float depth = eye.depth.depth.at(x, y);
      if (!(depth > 0.0f)) continue;
      const auto [mesh, triangle] = scene.locateTriangle(eye.primitive.at(x, y));
      const Mesh& m = scene.meshes[mesh];
      const dvec3 a(m.vertex(triangle, 0)), b(m.vertex(triangle, 1)), c(m.vertex(triangle, 2));
      const dvec3 n = glm::normalize(glm::cross(b - a, c - a));  // outward: CCW from outside
      const dvec3 p = view.unproject(x, y, depth);
      const double facing = glm::dot(n, glm::normalize(dvec3(light.center) - p));
      // The oracle measures from its offset origin: skip faces within ~0.2 degrees of edge-on.
      if (facing > 3e-3) {
        ASSERT_EQ(result.visibility.at(x, y), 1.0f) << "acne at pixel " << x << "," << y;
        ++lit;
      } else if (facing < -3e-3) {
        ASSERT_EQ(result.visibility.at(x, y), 0.0f) << "leak at pixel " << x << "," << y;
        ++dark;
      }
    }
  }
  EXPECT_GT(lit, 3000);
  EXPECT_GT(dark, 1000);
}

// A large plane seen and lit at grazing angles: depth precision is worst far away along it.
// If this failed, far ground points would shadow themselves.
TEST(ReferenceEyePass, GrazingGroundHasNoAcne) {
  Light light;
  light.center = vec3(-40.0f, 0.1f, -30.0f);
  const Scene scene = finalized({makeGroundPlane(vec3(0.0f), 100.0f)}, light);
  const View view = View::lookAt(256, 96, vec3(0.0f, 0.25f, 60.0f), vec3(0.0f, 0.0f, 0.0f),
                                 vec3(0, 1, 0), 60.0f, 0.05f);
  Stats eye_stats;
  const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
  const TechniqueResult result = renderReference(hardOptions(), scene, light, view, eye);
  int covered = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      covered += eye.depth.depth.at(x, y) > 0.0f ? 1 : 0;
      ASSERT_EQ(result.visibility.at(x, y), 1.0f) << "pixel " << x << "," << y;
    }
  }
  EXPECT_GT(covered, 5000);
}

// An inside corner: a floor meeting a wall at 90 degrees, both lit by a light in front of the
// wall. Everything is lit. The eye pass puts some corner pixels' points a hair beyond the
// floor's edge, inside the wall; put back on the floor they lie on the wall's plane, where a
// ray would hit the wall at t = 0. If this failed, origins are not kept off their triangle's
// edges and inside corners get a dark seam.
TEST(ReferenceEyePass, InsideCornerHasNoSeam) {
  Light light;
  light.center = vec3(3.0f, 2.5f, 0.7f);
  Mesh floor;
  floor.name = "floor";
  floor.positions = {vec3(0, 0, -2), vec3(0, 0, 2), vec3(4, 0, 2), vec3(4, 0, -2)};
  floor.indices = {0, 1, 2, 0, 2, 3};
  Mesh wall;
  wall.name = "wall";
  wall.positions = {vec3(0, 0, -2), vec3(0, 2, -2), vec3(0, 2, 2), vec3(0, 0, 2)};
  wall.indices = {0, 2, 1, 0, 3, 2};
  const Scene scene = finalized({floor, wall}, light);
  int covered = 0;
  // Several views along the corner: which pixels land beyond the edge depends on snapping.
  for (int i = 0; i < 4; ++i) {
    const View view = View::lookAt(160, 120, vec3(2.5f + 0.3f * i, 1.2f + 0.2f * i, 1.5f - i),
                                   vec3(0.0f, 0.2f, 0.1f * i), vec3(0, 1, 0), 50.0f, 0.05f);
    Stats eye_stats;
    const EyeBuffers eye = renderEyePass(scene, view, eye_stats);
    const TechniqueResult result = renderReference(hardOptions(), scene, light, view, eye);
    for (int y = 0; y < view.height; ++y) {
      for (int x = 0; x < view.width; ++x) {
        covered += eye.depth.depth.at(x, y) > 0.0f ? 1 : 0;
        ASSERT_EQ(result.visibility.at(x, y), 1.0f) << "view " << i << " pixel " << x << "," << y;
      }
    }
  }
  EXPECT_GT(covered, 40000);
}

}  // namespace test_reference_eye_pass
}  // namespace penumbra
