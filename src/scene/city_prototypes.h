#pragma once
// The meshes the built-in city places many times (builtin_city_scene.cpp), each in its own
// object space: standing on y = 0, centred on x = z = 0. Every one is closed: it is made of
// disjoint closed parts (boxes, cylinders, spheres), so shadow volumes are exact for it.
#include "scene/mesh.h"

namespace penumbra {

struct BuildingShape {
  float width = 12.0f;  // x extent of the lowest tier
  float depth = 12.0f;  // z extent of the lowest tier
  int floors = 10;      // of 3.2 units each
  int tiers = 1;        // setbacks: each tier above the first is narrower and holds fewer floors
  int windows = 5;      // window boxes per floor on each side of the lowest tier
};

// A tower of `tiers` boxes, a ledge slab at every floor and a window box (protruding from the
// facade) with a sill per window: about 12 * (1 + floors * (1 + 8 * windows)) triangles.
Mesh makeBuilding(const BuildingShape& shape);
// A trunk and a round crown, `height` tall.
Mesh makeTree(float height);
// A street lamp: pole, arm and lamp head.
Mesh makeStreetLamp(float height);
// A bench: seat, back and two legs.
Mesh makeBench();

}  // namespace penumbra
