#pragma once
// A mesh given as arrays in memory (a program's own geometry; numpy arrays from the Python
// module) instead of a file, checked and welded as the file loader's meshes are.
#include <cstdint>
#include <string>
#include <vector>

#include <penumbra/scene/mesh.h>

namespace penumbra {

struct MeshArrays {
  std::vector<float> vertices;     // x, y, z of each vertex
  std::vector<int64_t> triangles;  // 3 vertex indices per triangle, counter-clockwise from the front
};

// The mesh of `arrays`, welded (weld.h) with corner normals computed, as loadMesh returns a
// file's. Throws penumbra::Error naming `name` and what is wrong: a vertex or index count that
// is not a multiple of 3, no vertices or no triangles, a non-finite coordinate (any vertex's,
// used or not: a NaN in the array is a bug in its maker), an index out of range, or every
// triangle degenerate.
Mesh meshFromArrays(const MeshArrays& arrays, const std::string& name);

}  // namespace penumbra
