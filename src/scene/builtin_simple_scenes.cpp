// "spheres", "columns" and "multilight": small scenes of primitives on a floor.
#include "scene/builtin_scenes_impl.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "scene/scene_builder.h"
#include "scene/shapes.h"
#include "scene/teapot.h"

namespace penumbra {

namespace {

const vec3 kFloorAlbedo(0.72f, 0.71f, 0.68f);

}  // namespace

Scene makeSpheresScene() {
  // Spheres floating over a plane: the analytic sanity case (a sphere's shadow from a spherical
  // light has a closed-form umbra and penumbra on a plane).
  Scene scene;
  const uint32_t floor = addMaterial(scene, "floor", kFloorAlbedo);
  const uint32_t red = addMaterial(scene, "red", vec3(0.80f, 0.22f, 0.18f), vec3(0.3f), 48.0f);
  const uint32_t green = addMaterial(scene, "green", vec3(0.25f, 0.65f, 0.30f), vec3(0.3f), 48.0f);
  const uint32_t blue = addMaterial(scene, "blue", vec3(0.22f, 0.35f, 0.80f), vec3(0.3f), 48.0f);
  addMesh(scene, makeGroundPlane(vec3(0.0f), 30.0f), floor);
  addMesh(scene, makeSphere(vec3(-1.5f, 1.5f, 0.0f), 1.0f, 48, 24), red);
  addMesh(scene, makeSphere(vec3(1.1f, 1.0f, 1.0f), 0.55f, 40, 20), green);
  addMesh(scene, makeSphere(vec3(1.4f, 2.2f, -1.3f), 0.7f, 40, 20), blue);
  addMesh(scene, makeSphere(vec3(-0.3f, 0.5f, 2.0f), 0.3f, 32, 16), green);
  addLight(scene, vec3(3.0f, 7.0f, 3.0f), 0.4f);
  scene.camera.position = vec3(0.6f, 4.0f, 8.5f);
  scene.camera.target = vec3(0.0f, 0.7f, 0.0f);
  scene.camera.fov_y = 40.0f;
  return scene;
}

Scene makeColumnsScene() {
  // A colonnade under a low light from the side: long, grazing shadows across the floor, the
  // case where shadow volumes cover the most pixels.
  Scene scene;
  const uint32_t floor = addMaterial(scene, "floor", kFloorAlbedo);
  const uint32_t stone = addMaterial(scene, "stone", vec3(0.85f, 0.80f, 0.70f), vec3(0.1f), 16.0f);
  addMesh(scene, makeGroundPlane(vec3(0.0f), 40.0f), floor);
  constexpr int kColumns = 10;
  constexpr float kSpacing = 1.3f;
  for (int i = 0; i < kColumns; ++i) {
    const float x = (float(i) - 0.5f * float(kColumns - 1)) * kSpacing;
    // The shaft reaches 2 cm into the base and the capital: parts that only touched would have
    // coplanar faces (depth ties, and edges of zero-area contact).
    Mesh column = makeBox(vec3(x - 0.36f, 0.0f, -0.36f), vec3(x + 0.36f, 0.22f, 0.36f));
    appendMesh(column, makeCylinder(vec3(x, 0.20f, 0.0f), 0.24f, 2.94f, 24));
    appendMesh(column, makeBox(vec3(x - 0.36f, 3.12f, -0.36f), vec3(x + 0.36f, 3.34f, 0.36f)));
    column.name = "column";
    addMesh(scene, std::move(column), stone);
  }
  const float half_length = 0.5f * float(kColumns - 1) * kSpacing + 0.5f;
  addMesh(scene, makeBox(vec3(-half_length, 3.32f, -0.45f), vec3(half_length, 3.7f, 0.45f)), stone)
      .name = "architrave";
  addLight(scene, vec3(-10.0f, 4.2f, -4.0f), 0.35f, vec3(1.0f, 0.96f, 0.88f));
  scene.camera.position = vec3(-5.0f, 4.6f, 11.5f);
  scene.camera.target = vec3(-0.2f, 1.1f, 1.0f);
  scene.camera.fov_y = 45.0f;
  return scene;
}

Scene makeMultilightScene() {
  // Three coloured lights: each technique runs once per light and shading sums them, so the
  // overlapping coloured shadows show each light's visibility buffer separately.
  Scene scene;
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.8f));
  const uint32_t white = addMaterial(scene, "white", vec3(0.85f), vec3(0.25f), 40.0f);
  const uint32_t clay = addMaterial(scene, "clay", vec3(0.78f, 0.55f, 0.40f), vec3(0.2f), 24.0f);
  addMesh(scene, makeGroundPlane(vec3(0.0f), 30.0f), floor);
  addMesh(scene, makeSphere(vec3(-1.3f, 0.7f, 0.3f), 0.7f, 40, 20), white);
  addMesh(scene, makeBox(vec3(0.5f, 0.0f, -1.3f), vec3(1.4f, 1.2f, -0.4f)), clay);
  addMesh(scene, makeCylinder(vec3(0.2f, 0.0f, 1.1f), 0.3f, 1.5f, 32), white);
  Mesh ring = makeTorus(vec3(0.0f), 0.5f, 0.12f, 48, 16);
  transformMesh(ring, glm::rotate(glm::translate(mat4(1.0f), vec3(-0.2f, 1.9f, -0.6f)),
                                  glm::radians(60.0f), vec3(1.0f, 0.0f, 0.3f)));
  addMesh(scene, std::move(ring), clay);
  addLight(scene, vec3(-4.0f, 5.0f, 2.5f), 0.3f, vec3(1.0f, 0.45f, 0.30f), 0.6f);
  addLight(scene, vec3(4.5f, 5.5f, 1.5f), 0.3f, vec3(0.35f, 1.0f, 0.45f), 0.5f);
  addLight(scene, vec3(0.5f, 6.0f, -4.5f), 0.3f, vec3(0.35f, 0.5f, 1.0f), 0.6f);
  scene.camera.position = vec3(1.5f, 4.0f, 7.5f);
  scene.camera.target = vec3(0.0f, 0.6f, 0.0f);
  scene.camera.fov_y = 42.0f;
  return scene;
}

}  // namespace penumbra
