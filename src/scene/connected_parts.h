#pragma once
// The connected parts of a mesh's triangles: union-find over the welded positions they share.
#include <cstdint>
#include <vector>

#include "scene/mesh.h"

namespace penumbra {

// Per vertex of `mesh`, the connected part (0, 1, ...) of the triangles using it, in order of
// first use by a triangle; unused vertices get part 0. Returns the number of parts.
uint32_t connectedParts(const Mesh& mesh, std::vector<uint32_t>& part_of_vertex);

}  // namespace penumbra
