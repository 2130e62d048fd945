// A rough height field under a low light with a flattened ellipsoid floating over it (issue 9,
// item 5): where the ellipsoid alone hides the whole light from a point and the oracle has the
// point fully shadowed, no soft technique may light it by more than 0.1. A thin streak of light
// across that umbra is a wedge (or coverage) contribution of the terrain's jagged silhouette added
// where another occluder already hides everything; the umbra is wide, so a single such wedge
// shows up here as many pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "eye_frame_util.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "shadows/reference_options.h"
#include "shadows/stages/light_sampling/ray_origin.h"
#include "shadows/technique.h"

namespace penumbra {
namespace test_soft_terrain {

// The ellipsoid: the unit sphere scaled by kEllipsoidScale and moved to kEllipsoidCentre.
const vec3 kEllipsoidScale(1.8f, 0.45f, 1.4f);
const vec3 kEllipsoidCentre(-3.0f, 3.0f, 0.0f);

// Diamond-square terrain (half size 8, roughness 0.6, 8,192 triangles: an open height field),
// the light 1 in radius about 25 degrees above the horizon (atan(9.3 / 22)) beyond the terrain's
// border, seen from above the ellipsoid and its shadow.
Scene terrainScene() {
  Scene s;
  s.name = "terrain-low-light";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeFractalTerrain(6, 8.0f, 0.6f, 11u));
  Mesh ellipsoid = makeSphere(vec3(0.0f), 1.0f, 48, 24);
  transformMesh(ellipsoid, glm::translate(mat4(1.0f), kEllipsoidCentre) *
                               glm::scale(mat4(1.0f), kEllipsoidScale));
  s.meshes.push_back(std::move(ellipsoid));
  s.lights.push_back(Light{vec3(-22.0f, 9.3f, 0.0f), 1.0f, vec3(1.0f), 1.0f});
  s.camera.position = vec3(1.0f, 11.0f, 6.0f);
  s.camera.target = vec3(1.5f, 0.0f, 0.0f);
  s.camera.fov_y = 45.0f;
  s.finalize();
  return s;
}

// Whether the segment from p to q meets the ellipsoid shrunk by 2 %: the 48 x 24 polygon sphere
// holds that shrunk one (its faces are at least cos(pi/24) = 0.991 of the radius from the
// centre), so such a segment certainly meets the mesh too.
bool meetsShrunkEllipsoid(const dvec3& p, const dvec3& q) {
  const dvec3 scale = 0.98 * dvec3(kEllipsoidScale), centre(kEllipsoidCentre);
  const dvec3 o = (p - centre) / scale, d = (q - p) / scale;
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
  const double disc = b * b - a * c;
  if (disc < 0.0) return false;
  const double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
  return t1 > 0.0 && t0 < 1.0;
}

// In the ellipsoid's umbra: every segment to 24 points 5 % outside the light's rim, as seen from
// p, meets it (the ellipsoid is convex, so it then hides the whole light).
bool inEllipsoidUmbra(const dvec3& p, const Light& light) {
  const dvec3 c(light.center), dir = glm::normalize(c - p);
  const dvec3 u = glm::normalize(glm::cross(dir, dvec3(0.0, 0.0, 1.0))), v = glm::cross(dir, u);
  for (int k = 0; k < 24; ++k) {
    const double angle = k * 2.0 * 3.14159265358979 / 24.0;
    const dvec3 rim = c + 1.05 * double(light.radius) * (std::cos(angle) * u + std::sin(angle) * v);
    if (!meetsShrunkEllipsoid(p, rim)) return false;
  }
  return true;
}

TEST(SoftShadowTerrain, NoLightInTheFloatingOccludersUmbra) {
  const testing::EyeFrame f = testing::makeEyeFrame(terrainScene(), 160, 107);
  const Light& light = f.scene.lights[0];
  TechniqueConfig oracle_config("reference");
  oracle_config.options<ReferenceOptions>().rays = 256;
  const TechniqueResult oracle = renderShadows(oracle_config, f.scene, light, f.view, f.eye);

  const RayOrigins origins(f.scene, f.view);
  std::vector<size_t> umbra;  // pixels in the ellipsoid's umbra that the oracle has dark
  size_t umbra_lit_by_oracle = 0;
  for (int y = 0; y < f.view.height; ++y)
    for (int x = 0; x < f.view.width; ++x) {
      const size_t i = size_t(y) * size_t(f.view.width) + size_t(x);
      const float depth = f.eye.depth.depth[i];
      if (!(depth > 0.0f)) continue;
      const dvec3 p = origins.start(x, y, depth, f.eye.primitive[i]).origin;
      if (!inEllipsoidUmbra(p, light)) continue;
      if (oracle.visibility[i] == 0.0f) {
        umbra.push_back(i);
      } else {
        ++umbra_lit_by_oracle;
      }
    }
  // The scene must put a wide umbra on the terrain, and the geometric umbra test must agree with
  // the oracle there, or this test measures nothing.
  ASSERT_GT(umbra.size(), 300u);
  EXPECT_EQ(umbra_lit_by_oracle, 0u);

  std::vector<std::string> soft;
  for (const std::string& name : techniqueNames()) {
    const TechniqueInfo& info = findTechnique(name);
    if (info.traits.soft && !info.traits.ray_traced) soft.push_back(name);
  }
  ASSERT_FALSE(soft.empty());
  for (const std::string& name : soft) {
    const TechniqueResult r = renderShadows(TechniqueConfig(name), f.scene, light, f.view, f.eye);
    size_t lit = 0;
    float brightest = 0.0f;
    for (size_t i : umbra) {
      if (r.visibility[i] > 0.1f) ++lit;
      brightest = std::max(brightest, r.visibility[i]);
    }
    std::printf("[ terrain  ] %-14s umbra pixels %zu, lit > 0.1: %zu, brightest %.3f\n",
                name.c_str(), umbra.size(), lit, brightest);
    EXPECT_EQ(lit, 0u) << name << ": light leaks into the floating occluder's umbra";
  }
}

// Where the oracle has a terrain point fully shadowed, the wedges and the coverage volumes light
// few of them. The terrain is open: one facing casts (silhouette.h, SolidWithHoles), the
// light-facing one, so a ray from behind a ridge near the border that enters the ridge through
// its back and leaves through the terrain's open border crosses no light-facing triangle and its
// point came out lit; the other facing's pass (--one-facing turns it off) counts it. Measured at
// this size against 256 rays, of the 6,014 oracle-dark pixels lit by more than 0.1, one facing /
// both: wedge-3pass 6.4 % / 0.7 %, coverage 6.4 % / 0.7 % (the rest: silhouettes taken from the
// light centre, 2002 paper section 8). The bound 1.5 % fails if the second pass stops counting
// the rays through the border.
TEST(SoftShadowTerrain, RaysThroughAnOpenMeshsBorderStayDark) {
  const testing::EyeFrame f = testing::makeEyeFrame(terrainScene(), 160, 107);
  const Light& light = f.scene.lights[0];
  TechniqueConfig oracle_config("reference");
  oracle_config.options<ReferenceOptions>().rays = 256;
  const TechniqueResult oracle = renderShadows(oracle_config, f.scene, light, f.view, f.eye);
  size_t dark = 0;
  for (size_t i = 0; i < oracle.visibility.size(); ++i)
    if (f.eye.depth.depth[i] > 0.0f && oracle.visibility[i] == 0.0f) ++dark;
  ASSERT_GT(dark, 2000u);
  auto litWhereDark = [&](const std::string& technique, bool one_facing) {
    TechniqueConfig config(technique);
    config.set("one-facing", one_facing ? "true" : "false");
    const TechniqueResult r = renderShadows(config, f.scene, light, f.view, f.eye);
    size_t lit = 0;
    for (size_t i = 0; i < r.visibility.size(); ++i)
      if (f.eye.depth.depth[i] > 0.0f && oracle.visibility[i] == 0.0f && r.visibility[i] > 0.1f)
        ++lit;
    return double(lit) / double(dark);
  };
  for (const std::string technique : {"wedge-3pass", "coverage"}) {
    const double one = litWhereDark(technique, true), both = litWhereDark(technique, false);
    std::printf(
        "[ terrain  ] %-11s of %zu oracle-dark pixels lit > 0.1: one facing %.2f %%, "
        "both facings %.2f %%\n",
        technique.c_str(), dark, 100.0 * one, 100.0 * both);
    EXPECT_LE(both, 0.015) << technique;
    // The scene must show the leak the second pass removes, or the bound above proves nothing.
    EXPECT_GT(one, 2.0 * both) << technique;
  }
}

}  // namespace test_soft_terrain
}  // namespace penumbra
