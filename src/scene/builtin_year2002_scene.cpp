// "year2002": block digits "2002" floating over teapots on a floor (the 2002 paper's year scene
// in spirit: thin, many-edged casters whose penumbrae fall on curved receivers).
#include <string>

#include "core/error.h"
#include "scene/builtin_scenes_impl.h"
#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "scene/scene_builder.h"
#include "scene/teapot.h"

namespace penumbra {

namespace {

// Seven-segment digit: segments a (top), b (upper right), c (lower right), d (bottom),
// e (lower left), f (upper left), g (middle) as separate boxes with small gaps between them, so
// every box is its own closed component (touching boxes would share edges four ways).
Mesh makeBlockDigit(char digit, vec3 origin, float width, float height, float depth) {
  static constexpr const char* kSegments[10] = {"abcdef", "bc",     "abged", "abgcd", "fgbc",
                                                "afgcd",  "afgedc", "abc",   "abcdefg", "abcdfg"};
  PENUMBRA_CHECK(digit >= '0' && digit <= '9', "block digit '{}' is not 0-9", digit);
  const float t = 0.13f * height;  // bar thickness
  const float gap = 0.02f * height;
  const float mid = 0.5f * height;
  Mesh mesh;
  auto box = [&](float x0, float y0, float x1, float y1) {
    appendMesh(mesh, makeBox(origin + vec3(x0, y0, 0.0f), origin + vec3(x1, y1, depth)));
  };
  for (const char* s = kSegments[digit - '0']; *s; ++s) {
    switch (*s) {
      case 'a': box(0.0f, height - t, width, height); break;
      case 'g': box(0.0f, mid - 0.5f * t, width, mid + 0.5f * t); break;
      case 'd': box(0.0f, 0.0f, width, t); break;
      case 'f': box(0.0f, mid + 0.5f * t + gap, t, height - t - gap); break;
      case 'b': box(width - t, mid + 0.5f * t + gap, width, height - t - gap); break;
      case 'e': box(0.0f, t + gap, t, mid - 0.5f * t - gap); break;
      case 'c': box(width - t, t + gap, width, mid - 0.5f * t - gap); break;
    }
  }
  mesh.name = std::string("digit ") + digit;
  return mesh;
}

}  // namespace

Scene makeYear2002Scene() {
  Scene scene;
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.72f, 0.71f, 0.68f));
  const uint32_t digits = addMaterial(scene, "digits", vec3(0.85f, 0.62f, 0.20f), vec3(0.3f), 32.0f);
  const uint32_t china = addMaterial(scene, "china", vec3(0.80f, 0.82f, 0.88f), vec3(0.6f), 80.0f);
  addMesh(scene, makeGroundPlane(vec3(0.0f), 30.0f), floor);

  constexpr float kWidth = 1.0f, kHeight = 1.8f, kDepth = 0.3f, kSpacing = 0.35f;
  const std::string year = "2002";
  const float total = float(year.size()) * kWidth + float(year.size() - 1) * kSpacing;
  for (size_t i = 0; i < year.size(); ++i) {
    const vec3 origin(-0.5f * total + float(i) * (kWidth + kSpacing), 2.0f, -0.5f * kDepth);
    addMesh(scene, makeBlockDigit(year[i], origin, kWidth, kHeight, kDepth), digits);
  }
  const vec3 teapots[] = {vec3(-2.1f, 0.0f, -1.9f), vec3(0.1f, 0.0f, -2.4f), vec3(2.2f, 0.0f, -1.8f)};
  const float turns[] = {-30.0f, 15.0f, 60.0f};
  for (int i = 0; i < 3; ++i) {
    Mesh teapot = makeTeapot(vec3(0.0f), 1.3f);
    transformMesh(teapot, glm::rotate(glm::translate(mat4(1.0f), teapots[i]),
                                      glm::radians(turns[i]), vec3(0.0f, 1.0f, 0.0f)));
    addMesh(scene, std::move(teapot), china);
  }
  addLight(scene, vec3(1.0f, 8.0f, 3.5f), 0.45f);
  scene.camera.position = vec3(0.3f, 3.0f, 5.8f);
  scene.camera.target = vec3(0.0f, 1.3f, -1.4f);
  scene.camera.fov_y = 50.0f;
  return scene;
}

}  // namespace penumbra
