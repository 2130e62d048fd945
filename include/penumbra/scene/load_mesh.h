#pragma once
// Mesh files (OBJ, PLY, glTF/GLB, and whatever else assimp reads) into one welded Mesh.
#include <string>

#include <penumbra/scene/mesh.h>

namespace penumbra {

// Loads every triangle of the file (all sub-meshes merged, node transforms applied), welds
// positions (weld.h) and fills corner normals (from the file, else computed). Throws
// penumbra::Error naming the file and what is wrong: missing, unreadable, malformed, no
// triangles, non-finite coordinates.
Mesh loadMesh(const std::string& path);

}  // namespace penumbra
