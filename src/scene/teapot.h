#pragma once
// A procedural teapot (no data file is needed): a lathed body, a lid with a knob, a tapered bent
// spout and a handle. Not the Utah teapot, but the same silhouette family: a curved, self-
// shadowing object for the "year2002" scene.
#include "scene/mesh.h"

namespace penumbra {

// Teapot standing on `base_center` (spout towards +x, handle towards -x), `height` tall to the
// top of the knob. Every part is a closed, outward-facing mesh; they interpenetrate where they
// join, so the whole mesh is closed (each component is) but not a single surface.
Mesh makeTeapot(vec3 base_center, float height);

}  // namespace penumbra
