#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "render/shading.h"

namespace penumbra {
namespace test_output_shading {

constexpr int kSize = 33;  // odd: pixel (16, 16)'s centre is the image centre, on the view axis
constexpr int kCentre = kSize / 2;

// One triangle in the plane z = 0 around the origin, seen by an eye at (0, 0, 3) looking down
// -z. The light at (0, 4, 3) gives L = (0, 0.8, 0.6) at the origin, so n.L = 0.6 for n = +z.
Scene oneTriangleScene(bool front_facing = true) {
  Scene scene;
  scene.name = "one-triangle";
  Mesh mesh;
  mesh.name = "triangle";
  mesh.positions = {vec3(-1, -1, 0), vec3(1, -1, 0), vec3(0, 1, 0)};
  // Counter-clockwise seen from +z faces the eye; clockwise shows the eye its back.
  mesh.indices = front_facing ? std::vector<uint32_t>{0, 1, 2} : std::vector<uint32_t>{0, 2, 1};
  const vec3 n = front_facing ? vec3(0, 0, 1) : vec3(0, 0, -1);
  mesh.corner_normals = {n, n, n};
  scene.meshes.push_back(mesh);
  Material material;
  material.albedo = vec3(0.5f, 0.25f, 1.0f);
  material.specular = vec3(0.0f);
  scene.materials = {material};
  Light light;
  light.center = vec3(0, 4, 3);
  light.radius = 0.0f;
  light.color = vec3(1.0f, 0.5f, 1.0f);
  light.intensity = 2.0f;
  scene.lights = {light};
  scene.settings.ambient = vec3(0.1f, 0.2f, 0.3f);
  scene.settings.background = vec3(0.7f, 0.8f, 0.9f);
  scene.camera.position = vec3(0, 0, 3);
  scene.camera.target = vec3(0, 0, 0);
  scene.camera.up = vec3(0, 1, 0);
  scene.camera.fov_y = 45.0f;
  scene.camera.near_plane = 0.05f;
  scene.finalize();
  return scene;
}

// Every pixel sees the plane z = 0 at view distance 3 (it is perpendicular to the view axis);
// reversed-Z depth is near / distance (core/view.h). Every pixel names triangle 0: points off
// the triangle clamp to it, which the shading must tolerate.
EyeBuffers planeEyeBuffers(const View& view) {
  EyeBuffers eye;
  eye.depth.depth = Image<float>(view.width, view.height, view.near_plane / 3.0f);
  eye.primitive = Image<uint32_t>(view.width, view.height, 0u);
  return eye;
}

void expectColor(const vec3& got, const vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-4f);
  EXPECT_NEAR(got.y, want.y, 1e-4f);
  EXPECT_NEAR(got.z, want.z, 1e-4f);
}

// Lambert: albedo * n.L * colour * intensity + ambient * albedo = (0.65, 0.2, 1.5). A wrong
// light vector, a missing intensity or ambient, or shading the wrong point would change it.
TEST(OutputShading, LambertKnownValue) {
  const Scene scene = oneTriangleScene();
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const Image<float> visibility(kSize, kSize, 1.0f);
  const Image<vec3> color = shadeFrame(scene, view, eye, {&visibility});
  expectColor(color.at(kCentre, kCentre), vec3(0.65f, 0.2f, 1.5f));
  // A null visibility means unshadowed.
  expectColor(shadeFrame(scene, view, eye, {nullptr}).at(kCentre, kCentre),
              vec3(0.65f, 0.2f, 1.5f));
}

// Visibility scales only the light's term: 0 leaves exactly ambient * albedo, 0.5 halves the
// direct light (the papers' order: shadows modulate direct light, ambient is added after).
TEST(OutputShading, VisibilityModulatesDirectLightOnly) {
  const Scene scene = oneTriangleScene();
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const Image<float> dark(kSize, kSize, 0.0f);
  const Image<vec3> unlit = shadeFrame(scene, view, eye, {&dark});
  expectColor(unlit.at(kCentre, kCentre), vec3(0.05f, 0.05f, 0.3f));
  expectColor(unlit.at(3, 29), vec3(0.05f, 0.05f, 0.3f));  // any covered pixel
  const Image<float> half(kSize, kSize, 0.5f);
  expectColor(shadeFrame(scene, view, eye, {&half}).at(kCentre, kCentre),
              vec3(0.05f + 0.3f, 0.05f + 0.075f, 0.3f + 0.6f));
}

// Blinn-Phong: V = +z and L = (0, 0.8, 0.6) give n.H = 2 / sqrt(5), and (n.H)^8 = 0.8^4.
TEST(OutputShading, BlinnPhongSpecular) {
  Scene scene = oneTriangleScene();
  scene.materials[0].specular = vec3(0.5f);
  scene.materials[0].shininess = 8.0f;
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const Image<vec3> color = shadeFrame(scene, view, eye, {nullptr});
  const float spec = 0.5f * 0.4096f * 2.0f;  // specular * (n.H)^8 * intensity
  expectColor(color.at(kCentre, kCentre), vec3(0.65f + spec, 0.2f + spec * 0.5f, 1.5f + spec));
}

// A light behind the surface contributes neither diffuse nor specular.
TEST(OutputShading, LightBehindGivesAmbientOnly) {
  Scene scene = oneTriangleScene();
  scene.materials[0].specular = vec3(1.0f);
  scene.lights[0].center = vec3(0, 4, -3);
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  expectColor(shadeFrame(scene, view, eye, {nullptr}).at(kCentre, kCentre),
              vec3(0.05f, 0.05f, 0.3f));
}

// Open meshes are drawn two-sided: seen from its back, the triangle is lit like its front
// (the normal flips to face the eye), instead of going black.
TEST(OutputShading, BackFacesAreShadedFacingTheEye) {
  const Scene scene = oneTriangleScene(false);
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  expectColor(shadeFrame(scene, view, eye, {nullptr}).at(kCentre, kCentre),
              vec3(0.65f, 0.2f, 1.5f));
}

// The origin has barycentrics (1/4, 1/4, 1/2) in this triangle; with corner normals +z, +z and
// normalize(0, 1, 1) the interpolated normal leans 22.5 degrees toward +y.
TEST(OutputShading, InterpolatesCornerNormals) {
  Scene scene = oneTriangleScene();
  scene.meshes[0].corner_normals[2] = glm::normalize(vec3(0, 1, 1));
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const float angle = glm::radians(22.5f);
  const float n_dot_l = std::sin(angle) * 0.8f + std::cos(angle) * 0.6f;
  const vec3 albedo(0.5f, 0.25f, 1.0f);
  const vec3 want = albedo * n_dot_l * vec3(1.0f, 0.5f, 1.0f) * 2.0f + vec3(0.1f, 0.2f, 0.3f) * albedo;
  expectColor(shadeFrame(scene, view, eye, {nullptr}).at(kCentre, kCentre), want);
}

// Background pixels keep the scene's background colour whatever the lights do.
TEST(OutputShading, BackgroundPixels) {
  const Scene scene = oneTriangleScene();
  const View view = scene.camera.makeView(kSize, kSize);
  EyeBuffers eye = planeEyeBuffers(view);
  eye.primitive.at(0, 0) = kNoPrimitive;
  eye.depth.depth.at(0, 0) = 0.0f;
  const Image<vec3> color = shadeFrame(scene, view, eye, {nullptr});
  EXPECT_EQ(color.at(0, 0), vec3(0.7f, 0.8f, 0.9f));
  EXPECT_NE(color.at(1, 0), vec3(0.7f, 0.8f, 0.9f));
}

// Two lights add; each one's visibility applies to it alone.
TEST(OutputShading, LightsAddWithTheirOwnVisibility) {
  Scene scene = oneTriangleScene();
  Light second = scene.lights[0];
  second.center = vec3(0, 0, 10);  // n.L = 1 at the origin
  second.color = vec3(1.0f);
  second.intensity = 1.0f;
  scene.lights.push_back(second);
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const Image<float> lit(kSize, kSize, 1.0f);
  const Image<float> dark(kSize, kSize, 0.0f);
  const vec3 albedo(0.5f, 0.25f, 1.0f);
  expectColor(shadeFrame(scene, view, eye, {&dark, &lit}).at(kCentre, kCentre),
              vec3(0.05f, 0.05f, 0.3f) + albedo);
  expectColor(shadeFrame(scene, view, eye, {&lit, &lit}).at(kCentre, kCentre),
              vec3(0.65f, 0.2f, 1.5f) + albedo);
}

TEST(OutputShading, RejectsMismatchedBuffers) {
  const Scene scene = oneTriangleScene();
  const View view = scene.camera.makeView(kSize, kSize);
  const EyeBuffers eye = planeEyeBuffers(view);
  const Image<float> small(4, 4, 1.0f);
  EXPECT_THROW(shadeFrame(scene, view, eye, {}), Error);
  EXPECT_THROW(shadeFrame(scene, view, eye, {&small}), Error);
  const View other = scene.camera.makeView(kSize + 1, kSize);
  EXPECT_THROW(shadeFrame(scene, other, eye, {nullptr}), Error);
}

}  // namespace test_output_shading
}  // namespace penumbra
