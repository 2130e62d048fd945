#include "shadows/wedge/wedge_light_reach.h"

#include <fmt/format.h>

#include <algorithm>

namespace penumbra {

namespace {

double distanceToSegment(const dvec3& p, const dvec3& a, const dvec3& b) {
  const dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

}  // namespace

std::optional<EdgeInsideLight> edgeInsideLight(const Mesh& mesh, const Silhouette& silhouette,
                                               const Light& light) {
  const double r = double(light.radius);
  if (!(r > 0.0)) return std::nullopt;
  const dvec3 c(light.center);
  std::optional<EdgeInsideLight> nearest;
  for (const SilhouetteEdge& e : silhouette.edges) {
    const double d =
        distanceToSegment(c, dvec3(mesh.positions[e.v0]), dvec3(mesh.positions[e.v1]));
    // Not "d > r", so that a NaN distance is refused too.
    if (!(d > r) && (!nearest || d < nearest->distance)) nearest = EdgeInsideLight{e.v0, e.v1, d};
  }
  return nearest;
}

std::string edgeInsideLightMessage(const Mesh& mesh, const Light& light,
                                   const EdgeInsideLight& edge) {
  const vec3 a = mesh.positions[edge.v0], b = mesh.positions[edge.v1];
  return fmt::format(
      "penumbra wedges: the light at ({}, {}, {}) with radius {} reaches silhouette edge {}-{} "
      "(({}, {}, {}) to ({}, {}, {})) of mesh '{}', {:.6g} from its centre: the wedges need a "
      "light radius smaller than its distance to every silhouette edge; use a radius below "
      "{:.6g}, or --technique exact or reference, which take any radius",
      light.center.x, light.center.y, light.center.z, light.radius, edge.v0, edge.v1, a.x, a.y,
      a.z, b.x, b.y, b.z, mesh.name, edge.distance, edge.distance);
}

}  // namespace penumbra
