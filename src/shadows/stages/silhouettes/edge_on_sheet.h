#pragma once
// Casters edge-on to the light centre, for penumbra wedges.
//
// A triangle whose plane holds the light centre has no facing seen from there: its hard shadow
// is empty, but a soft light shines across it from both sides, and the triangle blocks the half
// of the light beyond its plane from points on the near side. So it leaves a thin penumbra line
// on either side of its plane on the receiver. The wedges build their penumbra from the
// silhouette seen from the centre: one facing gives the line on one side only, and the other
// facing's wedges, added into the same light-intensity buffer, exactly cancel it (each side's
// darkening is the other side's brightening past full light, and the buffer is clamped only
// at the end). So findSilhouette casts an edge-on triangle with the mesh's chosen facing
// (silhouette.h, SolidWithHoles), and the other facing is drawn into a light-intensity buffer
// of its own, clamped on its own, and the two visibilities are combined by taking the darker
// (wedge_technique.cpp). The darker, not the product: the sheet is usually part of a surface
// that already shadows the same points, and the wedges cannot tell how the two overlap. A
// triangle whose plane misses the centre by a hair (kEdgeOnRelative) has a facing, which its
// mesh may cast, but the light still shines across it from both sides almost equally: the
// other facing's pass takes it too.
#include <cstdint>

#include "scene/edges.h"
#include "scene/light.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {

// True when triangle (a, b, c) has an area and its plane passes within `tolerance` of `light`
// (in double, as findSilhouette decides facing; tolerance 0: exactly through it).
bool edgeOnToLight(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& light,
                   double tolerance);

// How near the light centre a plane counts as edge-on for the other facing's pass, relative
// to the light's radius: the light's two halves then differ by less than this fraction of the
// radius, so the facing seen from the centre says nothing about which half shines across. A
// caster meant to stand in the centre's plane lands off it by float rounding (a rotated
// generator: some 1e-7 of the radius), and would otherwise get one line only.
inline constexpr double kEdgeOnRelative = 1e-4;

// Whether any triangle of the scene is edge-on to the light (kEdgeOnRelative): the wedges'
// extra passes for the other facing run only then.
bool anyEdgeOnToLight(const Scene& scene, const Light& light);

// The silhouette of the mesh's triangles edge-on to the light (kEdgeOnRelative) cast with `facing` (+1 as wound, -1 flipped),
// leaving out those that `cast` (the mesh's own silhouette from the same centre) already casts
// with that facing and the repeated triangles (adjacency.repeated); every other triangle casts
// nothing. Empty edges when there is no such triangle.
Silhouette edgeOnSheet(const Mesh& mesh, const EdgeAdjacency& adjacency, const Light& light,
                       const Silhouette& cast, int8_t facing);

}  // namespace penumbra
