#pragma once
// Mesh generators for built-in scenes and tests. All return closed, consistently oriented
// meshes (counter-clockwise seen from outside) unless noted, with corner normals filled and
// positions welded (weld.h). Bad parameters throw penumbra::Error naming the generator.
// More shapes (lathe, tube, torus) are in shapes.h; the procedural teapot in teapot.h.
#include <cstdint>

#include "scene/mesh.h"

namespace penumbra {

// Generated meshes larger than this are refused before anything is allocated: a scene file
// asking for 2e9 segments would otherwise run for seconds and end in std::bad_alloc. At the
// limit a mesh takes about 250 MB (positions, indices, three normals per triangle); the
// largest built-in (fractal level 10) has 2^21 triangles.
constexpr int64_t kMaxGeneratedTriangles = int64_t(1) << 22;
// Throws penumbra::Error "<generator>: <what> make <triangles> triangles (the limit is ...)".
void checkGeneratedTriangles(const char* generator, const char* what, int64_t triangles);

Mesh makeBox(vec3 min, vec3 max);
// UV sphere: `segments` around the vertical axis, `rings` latitude bands; the poles are single
// vertices, so the sphere is a closed manifold. Normals are the exact sphere normals.
Mesh makeSphere(vec3 center, float radius, int segments = 32, int rings = 16);
// Vertical cylinder standing on `base_center`, capped at both ends.
Mesh makeCylinder(vec3 base_center, float radius, float height, int segments = 24);
// An open, one-sided square (2 triangles) in the plane y = center.y, facing +y (not closed).
Mesh makeGroundPlane(vec3 center, float half_size);
// A flat disk (open, facing `normal`), for the analytic disk-over-plane penumbra.
Mesh makeDisk(vec3 center, vec3 normal, float radius, int segments = 64);
// Diamond-square fractal height field of (2^level + 1)^2 vertices over [-half, half]^2 in x and
// z, deterministic for a seed (integer hashing, same on every platform); 2 * 4^level triangles
// (level 8: 131072). Open (a surface), facing +y, heights with mean 0. The coarsest step
// displaces by up to 0.5 * half_size * roughness and each finer step by `roughness` times the
// previous one, so roughness in (0, 1] sets both the height and the jaggedness (0.5: rolling
// hills). level is limited to 1..10.
Mesh makeFractalTerrain(int level, float half_size, float roughness, uint32_t seed);

}  // namespace penumbra
