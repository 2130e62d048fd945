#pragma once
// The potential silhouette edges (potential_edges.h) without those of the casters a frame's
// caster culling left out (caster_culling.h): the edges are found once per light and kept, the
// culling is the frame's, so a technique that keeps them filters a copy per frame.
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/potential_edges/potential_edges.h"

namespace penumbra {

// `edges` with every edge and cutting triangle of a culled mesh left out, the others in their
// order (an edge belongs to the mesh of its triangles).
PotentialEdges withoutCulledCasters(const PotentialEdges& edges, const Scene& scene,
                                    const CasterCulling& culling);

}  // namespace penumbra
