#include "scene/city_prototypes.h"

#include <algorithm>
#include <string>

#include "scene/generators.h"
#include "scene/mesh_ops.h"

namespace penumbra {

namespace {

constexpr float kFloorHeight = 3.2f;
// Parts of one prototype are kept this far apart (or overlap with no shared vertex), so that
// each stays its own closed component after welding (touching boxes would share edges four
// ways, as builtin_year2002_scene.cpp's digits explain).
constexpr float kPartGap = 0.02f;

void addBox(Mesh& mesh, vec3 min, vec3 max) { appendMesh(mesh, makeBox(min, max)); }

// The window boxes (each with a sill) of one facade: `count` per floor on a wall `wall_width`
// wide at `half_depth` from the centre along its normal axis (x when !along_x, else z), on the
// side `sign`.
void addWindows(Mesh& mesh, int floors, int count, float wall_width, float half_depth,
                bool along_x, float sign, float y0) {
  const float pitch = wall_width / float(count);
  const float w = 0.55f * pitch, h = 0.5f * kFloorHeight, protrude = 0.12f;
  for (int f = 0; f < floors; ++f) {
    const float y = y0 + float(f) * kFloorHeight + 0.35f * kFloorHeight;
    for (int k = 0; k < count; ++k) {
      const float along = -0.5f * wall_width + (float(k) + 0.5f) * pitch;
      // From just inside the wall to `protrude` outside it.
      const float n0 = sign * (half_depth - 0.05f), n1 = sign * (half_depth + protrude);
      const float a0 = along - 0.5f * w, a1 = along + 0.5f * w;
      const vec3 lo = along_x ? vec3(a0, y, std::min(n0, n1)) : vec3(std::min(n0, n1), y, a0);
      const vec3 hi =
          along_x ? vec3(a1, y + h, std::max(n0, n1)) : vec3(std::max(n0, n1), y + h, a1);
      addBox(mesh, lo, hi);
      // A sill under the window, wider and deeper, kept apart from it.
      const float s0 = sign * (half_depth - 0.05f), s1 = sign * (half_depth + 2.0f * protrude);
      const float b0 = a0 - 0.08f, b1 = a1 + 0.08f, sy = y - kPartGap;
      const vec3 slo =
          along_x ? vec3(b0, sy - 0.1f, std::min(s0, s1)) : vec3(std::min(s0, s1), sy - 0.1f, b0);
      const vec3 shi = along_x ? vec3(b1, sy, std::max(s0, s1)) : vec3(std::max(s0, s1), sy, b1);
      addBox(mesh, slo, shi);
    }
  }
}

}  // namespace

Mesh makeBuilding(const BuildingShape& shape) {
  Mesh mesh;
  float y = 0.0f, width = shape.width, depth = shape.depth;
  int windows = shape.windows;
  for (int tier = 0; tier < shape.tiers; ++tier) {
    // Lower tiers hold more of the floors: 1/2, 1/4, ... of what is left, the last the rest.
    const int left = shape.floors - int(y / kFloorHeight + 0.5f);
    const int floors = tier + 1 == shape.tiers ? left : std::max(1, left / 2);
    const float top = y + float(floors) * kFloorHeight;
    addBox(mesh, vec3(-0.5f * width, y, -0.5f * depth), vec3(0.5f * width, top, 0.5f * depth));
    for (int f = 1; f <= floors; ++f) {
      // A ledge slab around the facade under each floor's top, clear of the windows.
      const float ly = y + float(f) * kFloorHeight - 0.25f;
      const float lw = 0.5f * width + 0.2f, ld = 0.5f * depth + 0.2f;
      if (f < floors) addBox(mesh, vec3(-lw, ly, -ld), vec3(lw, ly + 0.15f + kPartGap, ld));
    }
    addWindows(mesh, floors, windows, width, 0.5f * depth, true, 1.0f, y);
    addWindows(mesh, floors, windows, width, 0.5f * depth, true, -1.0f, y);
    addWindows(mesh, floors, windows, depth, 0.5f * width, false, 1.0f, y);
    addWindows(mesh, floors, windows, depth, 0.5f * width, false, -1.0f, y);
    y = top + kPartGap;
    width *= 0.7f;
    depth *= 0.7f;
    windows = std::max(2, windows * 7 / 10);
  }
  finishMesh(mesh);
  mesh.name = "building";
  return mesh;
}

Mesh makeTree(float height) {
  Mesh mesh = makeCylinder(vec3(0.0f), 0.06f * height, 0.55f * height, 10);
  appendMesh(mesh, makeSphere(vec3(0.0f, 0.68f * height, 0.0f), 0.3f * height, 24, 14));
  finishMesh(mesh);
  mesh.name = "tree";
  return mesh;
}

Mesh makeStreetLamp(float height) {
  Mesh mesh = makeCylinder(vec3(0.0f), 0.06f, height, 12);
  addBox(mesh, vec3(-0.04f, height - 0.12f, -0.04f), vec3(0.7f, height - 0.04f, 0.04f));
  appendMesh(mesh, makeSphere(vec3(0.75f, height - 0.25f, 0.0f), 0.14f, 12, 8));
  finishMesh(mesh);
  mesh.name = "street lamp";
  return mesh;
}

Mesh makeBench() {
  Mesh mesh;
  addBox(mesh, vec3(-0.9f, 0.42f, -0.22f), vec3(0.9f, 0.48f, 0.22f));   // seat
  addBox(mesh, vec3(-0.9f, 0.52f, 0.24f), vec3(0.9f, 0.95f, 0.3f));     // back
  addBox(mesh, vec3(-0.8f, 0.0f, -0.18f), vec3(-0.7f, 0.4f, 0.18f));    // legs
  addBox(mesh, vec3(0.7f, 0.0f, -0.18f), vec3(0.8f, 0.4f, 0.18f));
  finishMesh(mesh);
  mesh.name = "bench";
  return mesh;
}

}  // namespace penumbra
