// "fractal": a ~131k-triangle diamond-square landscape as a complex receiver under floating
// occluders (the 2004 paper's landscape scene in spirit: many receiver triangles, few casters).
#include "scene/builtin_scenes_impl.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "scene/scene_builder.h"
#include "scene/shapes.h"

namespace penumbra {

Scene makeFractalScene() {
  Scene scene;
  const uint32_t ground = addMaterial(scene, "terrain", vec3(0.55f, 0.60f, 0.42f));
  const uint32_t metal = addMaterial(scene, "ring", vec3(0.75f, 0.70f, 0.62f), vec3(0.5f), 64.0f);
  const uint32_t red = addMaterial(scene, "red", vec3(0.78f, 0.25f, 0.20f), vec3(0.3f), 48.0f);
  addMesh(scene, makeFractalTerrain(8, 6.0f, 0.58f, 2002u), ground);
  Mesh ring = makeTorus(vec3(0.0f), 1.4f, 0.28f, 64, 20);
  transformMesh(ring, glm::rotate(glm::translate(mat4(1.0f), vec3(0.0f, 2.6f, 0.0f)),
                                  glm::radians(25.0f), vec3(1.0f, 0.0f, 0.4f)));
  addMesh(scene, std::move(ring), metal);
  addMesh(scene, makeSphere(vec3(-2.6f, 2.3f, 1.4f), 0.55f, 40, 20), red);
  addMesh(scene, makeBox(vec3(2.0f, 2.4f, -1.6f), vec3(2.9f, 2.8f, -0.7f)), red);
  addLight(scene, vec3(2.0f, 9.0f, 3.0f), 0.5f, vec3(1.0f, 0.97f, 0.92f));
  scene.camera.position = vec3(0.0f, 6.0f, 7.0f);
  scene.camera.target = vec3(0.0f, 0.3f, -0.8f);
  scene.camera.fov_y = 45.0f;
  return scene;
}

}  // namespace penumbra
