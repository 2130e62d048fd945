#pragma once
// Checks of a mesh file against what it declares, and of what the loader returned against the
// declaration and the vertex count, so that a file assimp misreads (a PLY of triangle strips
// comes back as one triangle, a short ASCII PLY gets made-up faces) is an error or a loud
// warning, never a silent success.
#include <string>

#include "scene/mesh.h"
#include "scene/ply_header.h"

namespace penumbra {

// Throws penumbra::Error naming the file for a PLY of triangle strips (assimp 5.2 reads them as
// one triangle). A body that does not match its header never gets this far (ply_check.h).
void checkPlyDeclaration(const std::string& path, const PlyHeader& ply);

// Distinct vertices the triangles use (indices out of range are not counted: weld.h refuses
// them).
size_t countReferencedVertices(const Mesh& mesh);

// After loading: `counts` holds the vertices and triangles read (before welding) and
// `referenced_vertices` how many of those vertices a triangle uses. Throws for a PLY whose
// declared faces gave fewer triangles; adds warnings to counts.warnings for files that loaded
// but look wrong (faces like strips, most vertices unused).
void checkLoadedCounts(const std::string& path, const PlyHeader& ply, size_t referenced_vertices,
                       MeshFileCounts& counts);

}  // namespace penumbra
