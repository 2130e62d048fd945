// "city": a procedural city of instanced buildings, trees, street lamps and benches on a grid
// of blocks (issue 32's big scene for occlusion and caster culling, after the thesis's P3 city
// walkthroughs). Each kind of object is one prototype placed many times (instances.h), so the
// scene description stays small at any size; "city:N" has N x N blocks.
#include <string>

#include "core/error.h"
#include "scene/builtin_scenes_impl.h"
#include "scene/city_prototypes.h"
#include "scene/generators.h"
#include "scene/hash.h"
#include "scene/scene_builder.h"

namespace penumbra {

namespace {

constexpr float kBlock = 40.0f;   // a block's side, sidewalks included
constexpr float kStreet = 12.0f;  // street width between blocks
constexpr float kPitch = kBlock + kStreet;
constexpr int kBuildingKinds = 8;

struct CityKinds {
  uint32_t buildings[kBuildingKinds];
  uint32_t tree, lamp, bench;
  uint32_t facade[3], foliage, metal, wood;
};

// Building variety from a fixed list: low wide blocks to setback towers.
CityKinds addCityPrototypes(Scene& scene) {
  CityKinds kinds{};
  const BuildingShape shapes[kBuildingKinds] = {
      {14.0f, 14.0f, 6, 1, 6},   {12.0f, 14.0f, 10, 1, 5}, {14.0f, 12.0f, 16, 2, 6},
      {12.0f, 12.0f, 24, 3, 5},  {10.0f, 14.0f, 8, 1, 4},  {14.0f, 14.0f, 30, 3, 7},
      {12.0f, 10.0f, 12, 2, 5},  {13.0f, 13.0f, 20, 2, 6},
  };
  for (int k = 0; k < kBuildingKinds; ++k) {
    Mesh building = makeBuilding(shapes[k]);
    building.name = "building " + std::to_string(k);
    kinds.buildings[k] = addPrototype(scene, std::move(building));
  }
  kinds.tree = addPrototype(scene, makeTree(7.0f));
  kinds.lamp = addPrototype(scene, makeStreetLamp(5.5f));
  kinds.bench = addPrototype(scene, makeBench());
  kinds.facade[0] = addMaterial(scene, "concrete", vec3(0.62f, 0.60f, 0.56f));
  kinds.facade[1] = addMaterial(scene, "brick", vec3(0.60f, 0.36f, 0.26f));
  kinds.facade[2] = addMaterial(scene, "glass", vec3(0.35f, 0.45f, 0.55f), vec3(0.5f), 64.0f);
  kinds.foliage = addMaterial(scene, "foliage", vec3(0.25f, 0.45f, 0.18f));
  kinds.metal = addMaterial(scene, "metal", vec3(0.3f, 0.3f, 0.32f), vec3(0.4f), 48.0f);
  kinds.wood = addMaterial(scene, "wood", vec3(0.5f, 0.35f, 0.2f));
  return kinds;
}

mat4 placeAt(vec3 position, float turn_degrees) {
  return glm::rotate(glm::translate(mat4(1.0f), position), glm::radians(turn_degrees),
                     vec3(0.0f, 1.0f, 0.0f));
}

// One block with its lower-left corner at (x0, z0): four lots of buildings, trees and lamps
// along its edges, benches between them. Kinds and turns come from a hash of the block's
// coordinates, the same on every platform.
void addBlock(Scene& scene, const CityKinds& kinds, int bx, int bz, float x0, float z0) {
  for (int lot = 0; lot < 4; ++lot) {
    const uint32_t h = hashCoords(32u, uint32_t(bx * 4 + lot), uint32_t(bz));
    const vec3 centre(x0 + (lot % 2 == 0 ? 0.3f : 0.7f) * kBlock, 0.0f,
                      z0 + (lot / 2 == 0 ? 0.3f : 0.7f) * kBlock);
    addInstance(scene, kinds.buildings[h % kBuildingKinds],
                placeAt(centre, float((h >> 8) % 4) * 90.0f), kinds.facade[(h >> 12) % 3]);
  }
  // Along the two edges facing the streets at z0 and x0: trees and lamps alternate.
  for (int k = 0; k < 4; ++k) {
    const float along = (float(k) + 0.5f) * kBlock / 4.0f;
    const uint32_t h = hashCoords(77u, uint32_t(bx * 8 + k), uint32_t(bz));
    const bool tree = k % 2 == 0;
    const uint32_t kind = tree ? kinds.tree : kinds.lamp;
    const uint32_t material = tree ? kinds.foliage : kinds.metal;
    addInstance(scene, kind,
                placeAt(vec3(x0 + along, 0.0f, z0 + 1.5f), tree ? float(h % 360) : -90.0f),
                material);
    addInstance(scene, kind,
                placeAt(vec3(x0 + 1.5f, 0.0f, z0 + along), tree ? float(h % 360) : 180.0f),
                material);
  }
  addInstance(scene, kinds.bench, placeAt(vec3(x0 + 0.5f * kBlock, 0.0f, z0 + 2.2f), 180.0f),
              kinds.wood);
  addInstance(scene, kinds.bench, placeAt(vec3(x0 + 2.2f, 0.0f, z0 + 0.5f * kBlock), 90.0f),
              kinds.wood);
}

// A walkthrough (`penumbra render city --path`): down from the starting view to eye height
// along the street, on to the far crossing and turning towards the centre of the city, while
// the sun moves across the sky (the moving shadows the thesis's walkthroughs show).
void addCityWalkthrough(Scene& scene, float street_x, float extent) {
  const float half = 0.5f * extent;
  ScenePath& path = scene.path;
  path.frames = 120;
  path.camera = {
      {0.0f, scene.camera.position, scene.camera.target, scene.camera.fov_y},
      {1.0f, vec3(street_x, 1.7f, 0.6f * half), vec3(street_x, 1.9f, 0.0f), 60.0f},
      {2.0f, vec3(street_x, 1.7f, -0.6f * half), vec3(street_x, 1.9f, -half), 60.0f},
      {3.0f, vec3(street_x, 6.0f, -0.8f * half), vec3(0.0f, 2.0f, -0.3f * half), 60.0f},
  };
  const vec3 sun = scene.lights[0].center;
  LightPath sun_path;
  sun_path.light = 0;
  sun_path.keys = {{0.0f, sun}, {3.0f, vec3(sun.z, sun.y, -sun.x)}};  // a quarter turn about y
  path.lights.push_back(sun_path);
}

}  // namespace

Scene makeCityScene(int blocks) {
  PENUMBRA_CHECK(blocks >= 1 && blocks <= kMaxCityBlocks,
                 "city: the size {} must be a whole number of blocks per side in 1..{}", blocks,
                 kMaxCityBlocks);
  Scene scene;
  const uint32_t ground = addMaterial(scene, "asphalt", vec3(0.32f, 0.32f, 0.33f));
  const CityKinds kinds = addCityPrototypes(scene);
  const float extent = float(blocks) * kPitch;
  const float origin = -0.5f * extent;
  addMesh(scene, makeGroundPlane(vec3(0.0f), 0.5f * extent + 2.0f * kPitch), ground);
  for (int bz = 0; bz < blocks; ++bz) {
    for (int bx = 0; bx < blocks; ++bx) {
      addBlock(scene, kinds, bx, bz, origin + float(bx) * kPitch + 0.5f * kStreet,
               origin + float(bz) * kPitch + 0.5f * kStreet);
    }
  }
  // A low afternoon sun, far away and large (soft shadows widen along the streets).
  addLight(scene, vec3(-0.6f, 0.9f, 0.45f) * (extent + 400.0f), 0.012f * (extent + 400.0f),
           vec3(1.0f, 0.95f, 0.85f));
  // From above the south-west corner across the city towards its centre: the view the
  // walkthrough starts from, before it comes down into the street between the first two
  // columns of blocks.
  const float street_x = origin + kPitch;  // the centre of that street
  scene.camera.position = vec3(street_x, 25.0f, 0.5f * extent + 25.0f);
  scene.camera.target = vec3(0.0f, 0.0f, -0.25f * extent);
  scene.camera.fov_y = 55.0f;
  scene.camera.near_plane = 0.2f;
  addCityWalkthrough(scene, street_x, extent);
  scene.settings.ambient = vec3(0.18f, 0.19f, 0.22f);
  scene.settings.background = vec3(0.45f, 0.6f, 0.8f);
  return scene;
}

}  // namespace penumbra
