#pragma once
// Mesh generators for built-in scenes and tests. All return closed, consistently oriented
// meshes (counter-clockwise seen from outside) unless noted, with corner normals filled.
#include "scene/mesh.h"

namespace penumbra {

Mesh makeBox(vec3 min, vec3 max);
Mesh makeSphere(vec3 center, float radius, int segments = 32, int rings = 16);
Mesh makeCylinder(vec3 base_center, float radius, float height, int segments = 24);
// An open, one-sided square in the plane y = height, facing +y (not closed).
Mesh makeGroundPlane(vec3 center, float half_size);
// A flat disk (open, facing `normal`), for the analytic disk-over-plane penumbra.
Mesh makeDisk(vec3 center, vec3 normal, float radius, int segments = 64);
// Diamond-square fractal height field of (2^level + 1)^2 vertices over [-half, half]^2,
// deterministic for a seed; 2 * 4^level triangles (level 8: ~131k). Open (a surface).
Mesh makeFractalTerrain(int level, float half_size, float roughness, uint32_t seed);

}  // namespace penumbra
