#include "shadows/stages/silhouettes/silhouette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/parallel.h"
#include "shadows/stages/silhouettes/edge_on_sheet.h"

namespace penumbra {
namespace {

enum class RayHit { Miss, Hit, Ambiguous };

// Moller-Trumbore in double; Ambiguous when the ray passes within a hair of an edge or vertex,
// where the parity of a crossing count cannot be trusted.
RayHit crossRay(const dvec3& o, const dvec3& d, const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 e1 = b - a, e2 = c - a;
  const dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-300) return RayHit::Miss;  // parallel to the plane
  const double inv = 1.0 / det;
  const dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  const dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  const double t = glm::dot(e2, q) * inv;
  constexpr double kHair = 1e-9;
  if (u < -kHair || v < -kHair || u + v > 1 + kHair || t < -kHair) return RayHit::Miss;
  if (u < kHair || v < kHair || u + v > 1 - kHair || t < kHair) return RayHit::Ambiguous;
  return RayHit::Hit;
}

// Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom and Strackee
// 1983), positive when the triangle is seen from its back (det(a, b, c) > 0).
double solidAngle(const dvec3& a, const dvec3& b, const dvec3& c) {
  const double num = glm::dot(a, glm::cross(b, c));
  if (num == 0.0) return 0.0;  // in the triangle's plane: no area seen (atan2 would give +-pi)
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double den =
      la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(num, den);
}

}  // namespace

double windingNumber(const Mesh& mesh, const dvec3& point, const std::vector<uint8_t>* skip) {
  const size_t n = mesh.triangleCount();
  std::vector<double> omega(n);
  parallelFor((n + 8191) / 8192, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 8192);
    for (size_t t = chunk * 8192; t < end; ++t)
      omega[t] = skip != nullptr && (*skip)[t] ? 0.0
                                               : solidAngle(dvec3(mesh.vertex(t, 0)) - point,
                                                            dvec3(mesh.vertex(t, 1)) - point,
                                                            dvec3(mesh.vertex(t, 2)) - point);
  });
  double sum = 0.0;  // in triangle order, so the result does not depend on the thread count
  for (const double o : omega) sum += o;
  return sum / (4.0 * std::numbers::pi);
}

bool insideClosedMesh(const Mesh& mesh, const dvec3& point, const std::vector<uint8_t>* skip) {
  // A closed mesh lies within its vertices' box: a point outside the box is outside the mesh,
  // without a ray through every triangle (findSilhouette asks once per mesh and light, every
  // frame; the light is seldom inside a caster's box). The vertices are floats, so the box's
  // bounds compare exactly with the point in double.
  const Bounds3 box = mesh.bounds();
  if (point.x < box.min.x || point.y < box.min.y || point.z < box.min.z || point.x > box.max.x ||
      point.y > box.max.y || point.z > box.max.z)
    return false;
  // Directions with no special alignment to axes or to each other; the next is tried when a ray
  // grazes an edge.
  static const std::array<dvec3, 4> kDirections = {glm::normalize(dvec3(0.5773, 0.6178, 0.5339)),
                                                   glm::normalize(dvec3(-0.3129, 0.8466, -0.4306)),
                                                   glm::normalize(dvec3(0.7071, -0.2213, -0.6716)),
                                                   glm::normalize(dvec3(-0.6109, -0.5521, 0.5673))};
  for (const dvec3& d : kDirections) {
    int crossings = 0;
    bool ambiguous = false;
    for (size_t t = 0; t < mesh.triangleCount() && !ambiguous; ++t) {
      if (skip != nullptr && (*skip)[t]) continue;
      const RayHit h = crossRay(point, d, dvec3(mesh.vertex(t, 0)), dvec3(mesh.vertex(t, 1)),
                                dvec3(mesh.vertex(t, 2)));
      crossings += h == RayHit::Hit;
      ambiguous = h == RayHit::Ambiguous;
    }
    if (!ambiguous) return (crossings & 1) != 0;
  }
  return false;  // every ray grazed an edge: the point is on the surface, call it outside
}

Silhouette findSilhouette(const Mesh& mesh, const EdgeAdjacency& adjacency, const vec3& light,
                          CasterPolicy policy) {
  Silhouette s;
  const size_t n = mesh.triangleCount();
  s.orientation.resize(n);
  const dvec3 l(light);
  // Which facing casts: +1 light-facing only, -1 facing-away only, 0 both (two-sided).
  int cast_only = 0;
  // Wedges cast each surface once: a repeated triangle would double its silhouette edges'
  // multiplicity and so the penumbra's darkening (repeated_triangles.h). Whether the mesh is
  // closed or consistently oriented is then judged without the repeats (a box stored twice is
  // closed). Shadow volumes count the repeats and shade the same, so they keep them.
  const bool other_facing = policy == CasterPolicy::SolidWithHolesOtherFacing;
  const bool once = policy == CasterPolicy::SolidWithHoles || other_facing;
  const bool closed = once ? adjacency.repeated.closed : mesh.closed;
  const size_t inconsistent =
      once ? adjacency.repeated.inconsistent_edges : adjacency.inconsistent_edges;
  std::vector<uint8_t> repeats;
  if (once && !adjacency.repeated.triangles.empty()) {
    repeats.assign(n, 0);
    for (const uint32_t t : adjacency.repeated.triangles) repeats[t] = 1;
  }
  const std::vector<uint8_t>* skip = repeats.empty() ? nullptr : &repeats;
  if (policy != CasterPolicy::TwoSided && closed) {
    cast_only = insideClosedMesh(mesh, l, skip) ? -1 : 1;
  } else if (once && inconsistent == 0) {
    // The facing that covers more of the light's view (silhouette.h). A tie (a closed part
    // seen from outside, up to rounding) goes to the light-facing side.
    cast_only = windingNumber(mesh, l, skip) > 0.0 ? -1 : 1;
    if (other_facing) cast_only = -cast_only;
  }
  // Facing in double: near-edge-on triangles must get one consistent sign for all their edges.
  parallelFor((n + 8191) / 8192, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 8192);
    for (size_t t = chunk * 8192; t < end; ++t) {
      const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
      const double side = glm::dot(glm::cross(b - a, c - a), l - a);
      int8_t facing = side > 0 ? 1 : (side < 0 ? -1 : 0);
      // An edge-on triangle (with an area) casts with the chosen facing for the wedges: it
      // blocks the half of a soft light beyond its plane (edge_on_sheet.h). Shadow volumes and
      // two-sided wedges leave it out: its hard volume is empty.
      if (facing == 0 && once && cast_only != 0 && edgeOnToLight(a, b, c, l, 0.0))
        facing = cast_only;
      s.orientation[t] = (cast_only == 0 || facing == cast_only) ? facing : 0;
    }
  });
  if (skip != nullptr)
    for (const uint32_t t : adjacency.repeated.triangles) s.orientation[t] = 0;
  s.edges = silhouetteEdges(adjacency, s.orientation);
  return s;
}

std::vector<SilhouetteEdge> silhouetteEdges(const EdgeAdjacency& adjacency,
                                            const std::vector<int8_t>& orientation) {
  std::vector<SilhouetteEdge> edges;
  for (size_t i = 0; i < adjacency.edges.size(); ++i) {
    const Edge& e = adjacency.edges[i];
    int32_t m = 0;
    for (uint32_t u = e.first_use; u < e.first_use + e.use_count; ++u)
      m += adjacency.uses[u].sign * orientation[adjacency.uses[u].triangle];
    if (m != 0) edges.push_back({e.v0, e.v1, m, uint32_t(i)});
  }
  return edges;
}

bool openMeshWithBothFacings(const Mesh& mesh, const EdgeAdjacency& adjacency, const vec3& light) {
  if (adjacency.open_edges == 0 || adjacency.repeated.closed ||
      adjacency.repeated.inconsistent_edges != 0)
    return false;
  const dvec3 l(light);
  const size_t n = mesh.triangleCount();
  std::vector<uint8_t> seen((n + 8191) / 8192, 0);  // bit 0: light-facing, bit 1: away
  parallelFor(seen.size(), [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 8192);
    for (size_t t = chunk * 8192; t < end && seen[chunk] != 3; ++t) {
      const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
      const double side = glm::dot(glm::cross(b - a, c - a), l - a);
      if (side > 0) seen[chunk] |= 1;
      if (side < 0) seen[chunk] |= 2;
    }
  });
  uint8_t both = 0;
  for (const uint8_t f : seen) both |= f;
  return both == 3;
}

std::vector<uint8_t> openMeshesWithBothFacings(const Scene& scene, const vec3& light) {
  std::vector<uint8_t> casts(scene.meshes.size(), 0);
  bool any = false;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    casts[m] = openMeshWithBothFacings(scene.meshes[m], scene.adjacency[m], light);
    any = any || casts[m] != 0;
  }
  if (!any) casts.clear();
  return casts;
}

}  // namespace penumbra
