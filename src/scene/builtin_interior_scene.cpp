// "interior": a reading hall under one lamp, N x N bays of bookshelves, tables and chairs, with
// columns, walls and a ceiling (issue 32's interior: a closed room where most of the scene is
// hidden behind shelves from any one view, as in the thesis's P3 indoor walkthroughs). Each
// kind of furniture is one prototype placed many times (instances.h).
#include <string>

#include "core/error.h"
#include "scene/builtin_scenes_impl.h"
#include "scene/generators.h"
#include "scene/hash.h"
#include "scene/mesh_ops.h"
#include "scene/scene_builder.h"

namespace penumbra {

namespace {

constexpr float kBay = 10.0f;        // a bay's side
constexpr float kHallHeight = 5.0f;  // floor to ceiling
constexpr float kShelfGap = 0.02f;   // between the parts of one prototype (closed components)

// A bookshelf 4 wide, 2.4 tall, 0.5 deep: two sides, five boards, and books of hashed widths
// and heights on each board, apart from each other and from the boards.
Mesh makeBookshelf() {
  Mesh mesh;
  const auto box = [&](vec3 lo, vec3 hi) { appendMesh(mesh, makeBox(lo, hi)); };
  box(vec3(-2.0f, 0.0f, -0.25f), vec3(-1.95f, 2.4f, 0.25f));
  box(vec3(1.95f, 0.0f, -0.25f), vec3(2.0f, 2.4f, 0.25f));
  for (int board = 0; board < 5; ++board) {
    const float y = 0.1f + float(board) * 0.55f;
    box(vec3(-1.95f + kShelfGap, y, -0.25f), vec3(1.95f - kShelfGap, y + 0.04f, 0.25f));
    if (board == 4) break;
    float x = -1.9f;
    for (uint32_t book = 0; x < 1.8f; ++book) {
      const uint32_t h = hashCoords(5u, uint32_t(board), book);
      const float width = 0.05f + 0.04f * (0.5f + 0.5f * signedUnit(h));
      const float height = 0.3f + 0.15f * (0.5f + 0.5f * signedUnit(mixBits(h)));
      if (x + width > 1.9f) break;
      box(vec3(x, y + 0.04f + kShelfGap, -0.18f),
          vec3(x + width, y + 0.04f + kShelfGap + height, 0.2f));
      x += width + kShelfGap;
    }
  }
  finishMesh(mesh);
  mesh.name = "bookshelf";
  return mesh;
}

Mesh makeTable() {
  Mesh mesh = makeBox(vec3(-1.0f, 0.72f, -0.5f), vec3(1.0f, 0.78f, 0.5f));
  for (const float x : {-0.9f, 0.85f}) {
    for (const float z : {-0.4f, 0.35f}) {
      appendMesh(mesh, makeBox(vec3(x, 0.0f, z), vec3(x + 0.05f, 0.72f - kShelfGap, z + 0.05f)));
    }
  }
  finishMesh(mesh);
  mesh.name = "table";
  return mesh;
}

Mesh makeChair() {
  Mesh mesh = makeBox(vec3(-0.22f, 0.43f, -0.22f), vec3(0.22f, 0.47f, 0.22f));
  appendMesh(mesh, makeBox(vec3(-0.22f, 0.47f + kShelfGap, 0.18f), vec3(0.22f, 0.95f, 0.22f)));
  for (const float x : {-0.2f, 0.17f}) {
    for (const float z : {-0.2f, 0.17f}) {
      appendMesh(mesh, makeBox(vec3(x, 0.0f, z), vec3(x + 0.03f, 0.43f - kShelfGap, z + 0.03f)));
    }
  }
  finishMesh(mesh);
  mesh.name = "chair";
  return mesh;
}

mat4 standAt(float x, float z, float turn_degrees) {
  return glm::rotate(glm::translate(mat4(1.0f), vec3(x, 0.0f, z)), glm::radians(turn_degrees),
                     vec3(0.0f, 1.0f, 0.0f));
}

// One bay centred at (cx, cz): two rows of shelves back to back on one side, a table with four
// chairs on the other, a column at the bay's corner.
void addBay(Scene& scene, const uint32_t (&kinds)[4], const uint32_t (&materials)[3], float cx,
            float cz) {
  const uint32_t shelf = kinds[0], table = kinds[1], chair = kinds[2], column = kinds[3];
  for (const float dz : {-3.5f, -1.0f, 1.5f}) {
    addInstance(scene, shelf, standAt(cx - 2.2f, cz + dz - 0.28f, 0.0f), materials[0]);
    addInstance(scene, shelf, standAt(cx - 2.2f, cz + dz + 0.28f, 180.0f), materials[0]);
  }
  addInstance(scene, table, standAt(cx + 2.5f, cz + 1.5f, 0.0f), materials[1]);
  for (const float dx : {-0.55f, 0.55f}) {
    addInstance(scene, chair, standAt(cx + 2.5f + dx, cz + 0.75f, 180.0f), materials[1]);
    addInstance(scene, chair, standAt(cx + 2.5f + dx, cz + 2.25f, 0.0f), materials[1]);
  }
  addInstance(scene, column, standAt(cx - 0.5f * kBay + 0.5f, cz - 0.5f * kBay + 0.5f, 0.0f),
              materials[2]);
}

// Four walls and a ceiling around the hall, apart from each other: each its own closed box.
void addHallShell(Scene& scene, float half, uint32_t material) {
  const float t = 0.3f, g = kShelfGap;
  addMesh(scene, makeBox(vec3(-half - t, 0.0f, -half - t), vec3(half + t, kHallHeight, -half)),
          material);
  addMesh(scene, makeBox(vec3(-half - t, 0.0f, half), vec3(half + t, kHallHeight, half + t)),
          material);
  addMesh(scene, makeBox(vec3(-half - t, 0.0f, -half + g), vec3(-half, kHallHeight, half - g)),
          material);
  addMesh(scene, makeBox(vec3(half, 0.0f, -half + g), vec3(half + t, kHallHeight, half - g)),
          material);
  addMesh(scene,
          makeBox(vec3(-half - t, kHallHeight + g, -half - t),
                  vec3(half + t, kHallHeight + t, half + t)),
          material);
}

}  // namespace

Scene makeInteriorScene(int bays) {
  PENUMBRA_CHECK(bays >= 1 && bays <= kMaxInteriorBays,
                 "interior: the size {} must be a whole number of bays per side in 1..{}", bays,
                 kMaxInteriorBays);
  Scene scene;
  const uint32_t floor = addMaterial(scene, "parquet", vec3(0.55f, 0.40f, 0.26f));
  const uint32_t plaster = addMaterial(scene, "plaster", vec3(0.80f, 0.78f, 0.72f));
  const uint32_t materials[3] = {
      addMaterial(scene, "oak", vec3(0.45f, 0.30f, 0.18f)),
      addMaterial(scene, "walnut", vec3(0.35f, 0.22f, 0.14f), vec3(0.2f), 40.0f),
      addMaterial(scene, "stone", vec3(0.70f, 0.68f, 0.64f))};
  const uint32_t kinds[4] = {addPrototype(scene, makeBookshelf()), addPrototype(scene, makeTable()),
                             addPrototype(scene, makeChair()),
                             addPrototype(scene, makeCylinder(vec3(0.0f), 0.3f, kHallHeight, 24))};
  const float half = 0.5f * float(bays) * kBay;
  addMesh(scene, makeGroundPlane(vec3(0.0f), half), floor);
  addHallShell(scene, half, plaster);
  for (int bz = 0; bz < bays; ++bz) {
    for (int bx = 0; bx < bays; ++bx) {
      addBay(scene, kinds, materials, -half + (float(bx) + 0.5f) * kBay,
             -half + (float(bz) + 0.5f) * kBay);
    }
  }
  // One lamp under the ceiling, off the hall's centre so the shelves' shadows fall at an angle.
  addLight(scene, vec3(0.3f * half, kHallHeight - 0.7f, 0.2f * half), 0.25f,
           vec3(1.0f, 0.9f, 0.75f));
  scene.camera.position = vec3(half - 0.8f, 1.7f, half - 0.8f);
  scene.camera.target = vec3(-0.3f * half, 1.0f, -0.3f * half);
  scene.camera.fov_y = 60.0f;
  scene.camera.near_plane = 0.05f;
  scene.settings.ambient = vec3(0.1f);
  // A walk along the hall's open side while the lamp slides the other way (a moving lamp).
  scene.path.frames = 60;
  scene.path.camera = {
      {0.0f, scene.camera.position, scene.camera.target, 60.0f},
      {1.0f, vec3(half - 0.8f, 1.7f, -half + 0.8f), vec3(-0.3f * half, 1.0f, 0.3f * half), 60.0f}};
  LightPath lamp;
  lamp.keys = {{0.0f, scene.lights[0].center},
               {1.0f, vec3(-0.3f * half, kHallHeight - 0.7f, -0.2f * half)}};
  scene.path.lights.push_back(lamp);
  return scene;
}

}  // namespace penumbra
