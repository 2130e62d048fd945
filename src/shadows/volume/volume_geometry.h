#pragma once
// Shadow volume polygons of one mesh, in clip space, ready for the stencil pass.
#include "core/view.h"
#include "raster/triangle_setup.h"
#include "scene/mesh.h"
#include "shadows/silhouette.h"

namespace penumbra {

// Appends to `out` the side quads of every silhouette edge, extruded from the light centre to
// infinity (w = 0), and with `zfail` also the light caps (the casting triangles) and dark caps
// (the same, projected to infinity). Payloads are signed weights of polygons facing out of the
// volume (rasterizer.h, rasterizeStencil). Cap vertices are transformed by the same
// View::toClip and kept in the mesh's own vertex order as in the eye pass, so a light cap lands
// bit-identically on the visible surface it comes from; its flip is a negated weight instead.
void appendVolumePolygons(const Mesh& mesh, const Silhouette& silhouette, const vec3& light,
                          const View& view, bool zfail, ClipTriangles& out);

}  // namespace penumbra
