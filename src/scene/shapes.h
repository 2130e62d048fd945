#pragma once
// Swept shapes the generators and the procedural teapot are built from. All closed and
// counter-clockwise seen from outside, corner normals filled.
#include <vector>

#include "scene/mesh.h"

namespace penumbra {

// Surface of revolution about the vertical axis through `base`. `profile` lists (radius, height)
// points from the bottom to the top; a point with radius exactly 0 is a pole (one vertex). The
// mesh is closed when the profile starts and ends on the axis. `crease_degrees` as in normals.h.
Mesh makeLathe(vec3 base, const std::vector<vec2>& profile, int segments,
               float crease_degrees = 45.0f);

// A tube of circular cross-section along `path` (at least 2 points), with radius radii[k] at
// path[k]. An open path is capped with a flat fan at each end; a loop joins its last ring to the
// first (no caps). Cross-sections are oriented by parallel transport along the path.
Mesh makeTube(const std::vector<vec3>& path, const std::vector<float>& radii, int sides, bool loop);

// A torus around the vertical axis through `center`.
Mesh makeTorus(vec3 center, float major_radius, float minor_radius, int segments = 48,
               int sides = 16);

}  // namespace penumbra
