#pragma once
// The silhouettes stage's debug layer (kSilhouetteEdgesLayer, shadows/technique.h): each
// silhouette edge seen from the light centre drawn as a one-pixel line where the eye sees it,
// over whatever hides it, as the papers' figures draw the edges the wedges are built on.
#include "core/image.h"
#include "core/math.h"
#include "core/view.h"
#include "scene/mesh.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {

// Adds 1 to every pixel the segment a-b (world space) covers on screen, the part behind the
// near plane cut off.
void drawWorldSegment(const View& view, const vec3& a, const vec3& b, Image<float>& layer);

// Every edge of `edges` (welded vertex indices of `mesh`).
void drawSilhouetteEdges(const Mesh& mesh, const std::vector<SilhouetteEdge>& edges,
                         const View& view, Image<float>& layer);

}  // namespace penumbra
