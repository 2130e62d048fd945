#pragma once
#include "scene/mesh.h"

namespace penumbra {

// Fills mesh.corner_normals with area-weighted vertex normals over the welded mesh, falling back
// to the face normal at corners whose face bends more than `crease_degrees` from the average,
// so cubes stay faceted and spheres smooth. Zero-area triangles get their neighbours' normal
// or (0, 1, 0).
void computeCornerNormals(Mesh& mesh, float crease_degrees = 45.0f);

}  // namespace penumbra
