#pragma once
// Casters whose shadow volume an eye ray enters many times: the cases where the hard volumes'
// count per pixel exceeds 1 for a single caster, which convex casters never reach.
//  - a comb: one connected, closed, non-convex mesh whose teeth's shadows an eye ray grazing
//    the ground crosses one after the other (one volume, entered once per tooth);
//  - a grid of boxes merged into one mesh under a low light: most of the floor lies in the
//    shadow of several boxes at once.
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "scene/generators.h"
#include "scene/mesh_ops.h"
#include "scene/scene.h"

namespace penumbra::testing {

// A comb lying flat between heights y0 and y1: `teeth` teeth 0.8 wide along x at x = 0, 1, ...,
// from z = -2 to 2, joined by a spine from z = 2 to 2.5. Closed and welded: its top and bottom
// are the comb's outline cut into strips (no T-junctions), its walls one quad per outline edge.
inline Mesh makeComb(int teeth, float y0, float y1) {
  std::vector<float> xs;
  for (int i = 0; i < teeth; ++i) {
    xs.push_back(float(i) - 0.4f);
    xs.push_back(float(i) + 0.4f);
  }
  const float zs[3] = {-2.0f, 2.0f, 2.5f};
  using Corner = std::pair<int, int>;  // (x index, z index)
  std::vector<std::array<Corner, 3>> caps;
  for (int s = 0; s + 1 < int(xs.size()); ++s) {
    const auto quad = [&](int z0, int z1) {
      caps.push_back({Corner{s, z0}, Corner{s + 1, z0}, Corner{s + 1, z1}});
      caps.push_back({Corner{s, z0}, Corner{s + 1, z1}, Corner{s, z1}});
    };
    if (s % 2 == 0) quad(0, 1);  // a tooth
    quad(1, 2);                  // the spine
  }
  Mesh mesh;
  mesh.name = "comb";
  std::map<std::pair<Corner, int>, uint32_t> ids;
  const auto at = [&](Corner c, int top) {
    auto [it, added] = ids.try_emplace({c, top}, uint32_t(mesh.positions.size()));
    if (added) mesh.positions.push_back(vec3(xs[c.first], top ? y1 : y0, zs[c.second]));
    return it->second;
  };
  // Adds a triangle wound so that its normal points along `out`.
  const auto add = [&](uint32_t a, uint32_t b, uint32_t c, vec3 out) {
    const vec3 n = cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    if (dot(n, out) < 0.0f) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  std::map<std::pair<Corner, Corner>, std::pair<int, vec3>> edges;  // uses, a triangle's centre
  for (const auto& t : caps) {
    add(at(t[0], 1), at(t[1], 1), at(t[2], 1), vec3(0, 1, 0));
    add(at(t[0], 0), at(t[1], 0), at(t[2], 0), vec3(0, -1, 0));
    const vec3 centre = (mesh.positions[at(t[0], 0)] + mesh.positions[at(t[1], 0)] +
                         mesh.positions[at(t[2], 0)]) / 3.0f;
    for (int e = 0; e < 3; ++e) {
      Corner a = t[e], b = t[(e + 1) % 3];
      if (b < a) std::swap(a, b);
      auto& use = edges[{a, b}];
      ++use.first;
      use.second = centre;
    }
  }
  for (const auto& [edge, use] : edges) {
    if (use.first != 1) continue;  // inside the outline
    const uint32_t a0 = at(edge.first, 0), b0 = at(edge.second, 0);
    const uint32_t a1 = at(edge.first, 1), b1 = at(edge.second, 1);
    vec3 out = (mesh.positions[a0] + mesh.positions[b0]) * 0.5f - use.second;
    out.y = 0.0f;
    add(a0, b0, b1, out);
    add(a0, b1, a1, out);
  }
  finishMesh(mesh);
  return mesh;
}

// The comb `teeth` teeth long 4 above a ground plane, lit from straight above; the eye low on
// the x axis looks along it at the ground under tooth 0, so its rays cross the shadows of the
// teeth in front (one volume entered up to `teeth` times).
inline Scene combOverGround(int teeth) {
  Scene s;
  s.name = "comb-over-ground";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0), 40.0f));
  s.meshes.push_back(makeComb(teeth, 4.0f, 4.2f));
  s.lights.push_back(Light{vec3(0, 20, 0), 0.0f, vec3(1), 1.0f});
  s.camera.position = vec3(float(teeth) + 3.0f, 3.0f, 0.0f);
  s.camera.target = vec3(0.0f);
  s.camera.fov_y = 30.0f;
  s.camera.near_plane = 0.05f;
  s.finalize();
  return s;
}

// A 4 x 4 grid of boxes merged into one caster mesh just above a ground plane (not touching it:
// no volume polygon lies in the floor), under a light 2.5 above
// the ground 12 away: each box's shadow runs across the boxes behind it, and the floor between
// them lies in up to four boxes' shadows.
inline Scene boxGridUnderLowLight() {
  Scene s;
  s.name = "box-grid-low-light";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0), 30.0f));
  Mesh grid;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const float x = -2.25f + 1.5f * float(i), z = -2.25f + 1.5f * float(j);
      appendMesh(grid, makeBox(vec3(x - 0.3f, 0.05f, z - 0.3f), vec3(x + 0.3f, 0.85f, z + 0.3f)));
    }
  grid.name = "box-grid";
  grid.corner_normals.clear();
  finishMesh(grid);
  s.meshes.push_back(std::move(grid));
  s.lights.push_back(Light{vec3(-12.0f, 2.5f, 1.0f), 0.0f, vec3(1), 1.0f});
  s.camera.position = vec3(7.0f, 6.0f, 7.0f);
  s.camera.target = vec3(0.0f);
  s.camera.fov_y = 50.0f;
  s.camera.near_plane = 0.05f;
  s.finalize();
  return s;
}

}  // namespace penumbra::testing
