#pragma once
// Small whole-mesh operations shared by the generators, the built-in scenes and scene files.
#include "scene/mesh.h"

namespace penumbra {

// Applies an affine transform to positions (and corner normals, by the inverse transpose).
// A mirroring transform (negative determinant) swaps two corners of every triangle so the
// winding stays counter-clockwise from the front. Re-welds afterwards, since rounding can make
// two positions equal or produce -0.0. Throws penumbra::Error for a singular or non-finite
// transform.
void transformMesh(Mesh& mesh, const mat4& transform);

// Appends `src`'s vertices and triangles to `dst` (indices offset; corner normals kept when both
// have them). Positions are not re-welded: call weldPositions if the two may touch.
void appendMesh(Mesh& dst, const Mesh& src);

// Last step of every generator: welds positions (weld.h: canonical +0.0, no duplicates) and
// computes corner normals when the generator left them empty.
void finishMesh(Mesh& mesh, float crease_degrees = 45.0f);

// Signed volume enclosed by a closed mesh (positive when its triangles face outwards). Used by
// tests and checks of the generators' orientation.
double signedVolume(const Mesh& mesh);

}  // namespace penumbra
