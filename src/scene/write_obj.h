#pragma once
// A mesh as a triangulated OBJ (positions and faces only): how scripts/fetch-models.sh stores a
// model it read with our loaders, so every model in the cache is a file any tool opens.
#include <string>
#include <vector>

#include "scene/mesh.h"

namespace penumbra {

// Writes `comments` as "# " lines, then the vertices, then the triangles. Each coordinate is the
// shortest decimal that reads back as the same float, so loading the file gives the mesh bit for
// bit. Written to PATH.partial and renamed, so a failure leaves no half-written file; throws
// penumbra::Error naming the file when a write fails.
void writeObj(const std::string& path, const Mesh& mesh, const std::vector<std::string>& comments);

}  // namespace penumbra
