#pragma once
// Triangles that repeat another triangle's three vertices in the same winding: a surface stored
// twice (an exporter that writes every face twice, two copies of a mesh merged into one file).
// A face and its reverse are a two-sided sheet and stay (scanned meshes such as dragon-res2 have
// some 1400 such pairs; dropping one of each opened holes there). Shadow volumes count them twice
// and still shade right; penumbra wedges add one penumbra per unit of silhouette multiplicity and
// would darken the penumbra twice around the whole outline, so the wedges' caster choice leaves the
// repeats out (silhouette.h).
#include <cstdint>
#include <vector>

#include "scene/edges.h"

namespace penumbra {

// The triangles of `mesh` that repeat an earlier one (RepeatedTriangles, edges.h). Linear in
// the edge uses: two triangles with the same vertex set share every edge, so it is enough to
// compare, per edge, the vertices opposite it (hashed where an edge has many uses).
RepeatedTriangles findRepeatedTriangles(const Mesh& mesh, const EdgeAdjacency& adjacency);

}  // namespace penumbra
