#pragma once
#include "scene/mesh.h"

namespace penumbra {

// Fills mesh.corner_normals (3 per triangle, unit length) over the welded mesh. Each corner
// averages, weighted by area, the normals of the triangles around its vertex that bend at most
// `crease_degrees` from its own triangle, so cubes stay faceted and spheres smooth. Around
// vertices of very high valence (> 256 triangles) a corner takes the vertex's full average when
// its face is within the crease angle of it, else the face normal. Zero-area triangles get
// their neighbours' normal or (0, 1, 0).
void computeCornerNormals(Mesh& mesh, float crease_degrees = 45.0f);

}  // namespace penumbra
