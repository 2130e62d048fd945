#pragma once
// The wedge construction's precondition on the light's size. A wedge is bounded by two planes
// through its silhouette edge that touch the light sphere on either side (2002 paper, section
// 4.1); they exist only while the edge lies outside the sphere. Where the light reaches an edge
// (its radius is at least its distance to the edge), the planes turn by nearly 90 degrees or
// more, the wedges swallow the scene behind the edge, and their additive intensities give
// floors far too dark, star-burst streaks and half-black floors: no image can be trusted, so
// the frame is refused with a message that names the light, the mesh and the edge.
#include <cstdint>
#include <optional>
#include <string>

#include "scene/light.h"
#include "scene/mesh.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {

struct EdgeInsideLight {
  uint32_t v0 = 0, v1 = 0;  // the silhouette edge's welded vertices
  double distance = 0.0;    // from the light centre to the edge segment
};

// The silhouette edge nearest the light centre among those whose distance is <= the radius
// (in double, the segment, not its line: an edge pointing at the light is fine until the
// light reaches its end); nullopt when every edge is outside the light or the radius is 0.
std::optional<EdgeInsideLight> edgeInsideLight(const Mesh& mesh, const Silhouette& silhouette,
                                               const Light& light);

// "penumbra wedges: the light at (x, y, z) with radius r reaches silhouette edge ... of mesh
// 'name' ...: the wedges need ...; use ...".
std::string edgeInsideLightMessage(const Mesh& mesh, const Light& light,
                                   const EdgeInsideLight& edge);

}  // namespace penumbra
