#include "shadows/stages/potential_edges/potential_edges.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace penumbra {
namespace {

constexpr size_t kEdgesPerItem = 2048;  // edges per work item

// Relative slack of the "plane cuts the ball" and "silhouette from the centre" tests: an edge
// kept needlessly costs a little time, an edge missed is a wrong pixel.
constexpr double kSlack = 1e-6;

int sign(double v) { return (v > 0.0) - (v < 0.0); }

}  // namespace

int circumscribedPyramid(const dvec3& c, double r, const dvec3& m, double rho, dvec4 planes[4]) {
  const double distance = glm::length(m - c);
  const double sin_gamma = (r + rho) / distance * (1.0 + 1e-9);
  if (!(sin_gamma < 0.9)) return 0;
  const dvec3 d = (m - c) / distance;
  const dvec3 apex = c + (m - c) * (r / (r + rho));
  const double cos_gamma = std::sqrt(1.0 - sin_gamma * sin_gamma);
  const dvec3 helper = std::fabs(d.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  const dvec3 t1 = glm::normalize(glm::cross(d, helper)), t2 = glm::cross(d, t1);
  const dvec3 sides[4] = {t1, -t1, t2, -t2};
  for (int k = 0; k < 4; ++k) {
    const dvec3 n = sin_gamma * d - cos_gamma * sides[k];
    planes[k] = dvec4(n, -glm::dot(n, apex));
  }
  return 4;
}

namespace {

// The vertex of triangle t of `mesh` that is neither v0 nor v1.
dvec3 oppositeVertex(const Mesh& mesh, size_t t, uint32_t v0, uint32_t v1) {
  dvec3 opposite(0.0);
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = mesh.indices[t * 3 + size_t(k)];
    if (v != v0 && v != v1) opposite = dvec3(mesh.positions[v]);
  }
  return opposite;
}

}  // namespace

EdgeGeometry edgeGeometry(const Scene& scene) {
  EdgeGeometry out;
  out.planes.resize(scene.meshes.size());
  out.winding.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const EdgeAdjacency& adjacency = scene.adjacency[m];
    std::vector<dvec4>& planes = out.planes[m];
    planes.resize(mesh.triangleCount());
    parallelFor((mesh.triangleCount() + kEdgesPerItem - 1) / kEdgesPerItem, [&](size_t chunk) {
      const size_t end = std::min(mesh.triangleCount(), (chunk + 1) * kEdgesPerItem);
      for (size_t t = chunk * kEdgesPerItem; t < end; ++t) {
        const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), v(mesh.vertex(t, 2));
        const dvec3 n = glm::cross(b - a, v - a);
        const double length = glm::length(n);
        planes[t] = length > 0.0 && std::isfinite(length)
                        ? dvec4(n / length, -glm::dot(n / length, a))
                        : dvec4(0.0);
      }
    });
    // The side of each use's triangle seen along its edge, from the triangle's own plane (not
    // from its index order: the same rounding every later plane test sees).
    std::vector<int8_t>& winding = out.winding[m];
    winding.assign(adjacency.uses.size(), 1);
    const size_t edge_count = adjacency.edges.size();
    parallelFor((edge_count + kEdgesPerItem - 1) / kEdgesPerItem, [&](size_t chunk) {
      const size_t end = std::min(edge_count, (chunk + 1) * kEdgesPerItem);
      for (size_t i = chunk * kEdgesPerItem; i < end; ++i) {
        const Edge& edge = adjacency.edges[i];
        const dvec3 a(mesh.positions[edge.v0]), b(mesh.positions[edge.v1]);
        for (uint32_t u = 0; u < edge.use_count; ++u) {
          const uint32_t t = adjacency.uses[edge.first_use + u].triangle;
          const dvec3 opposite = oppositeVertex(mesh, t, edge.v0, edge.v1);
          winding[edge.first_use + u] =
              glm::dot(dvec3(planes[t]), glm::cross(b - a, opposite - a)) >= 0.0 ? int8_t(1)
                                                                                 : int8_t(-1);
        }
      }
    });
  }
  return out;
}

namespace {

// Per triangle of a mesh, once (an edge asks for two): the side of its plane the light centre
// is on (-1, 0, +1; 0 also for zero area), and whether the plane cuts the ball (with slack: a
// triangle counted sample by sample is exact too).
struct TriangleSides {
  std::vector<int8_t> centre_side;
  std::vector<uint8_t> cuts;
};
TriangleSides triangleSides(const Mesh& mesh, const std::vector<dvec4>& planes, const dvec3& c,
                            double r) {
  TriangleSides sides;
  sides.centre_side.assign(mesh.triangleCount(), 0);
  sides.cuts.assign(mesh.triangleCount(), 0);
  parallelFor((mesh.triangleCount() + kEdgesPerItem - 1) / kEdgesPerItem, [&](size_t chunk) {
    const size_t end = std::min(mesh.triangleCount(), (chunk + 1) * kEdgesPerItem);
    for (size_t t = chunk * kEdgesPerItem; t < end; ++t) {
      const dvec4& plane = planes[t];
      if (plane == dvec4(0.0)) continue;
      const double at_centre = glm::dot(dvec3(plane), c) + plane.w;
      sides.centre_side[t] = int8_t(sign(at_centre));
      const double scale = glm::length(dvec3(mesh.vertex(t, 0)) - c) + r;
      sides.cuts[t] = std::fabs(at_centre) <= r * (1.0 + kSlack) + kSlack * scale;
    }
  });
  return sides;
}

void appendCuttingTriangles(const Mesh& mesh, const std::vector<dvec4>& planes,
                            const TriangleSides& sides, uint32_t first_id, const dvec3& c,
                            double r, std::vector<CuttingTriangle>& out) {
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!sides.cuts[t]) continue;
    CuttingTriangle cut;
    cut.id = first_id + uint32_t(t);
    for (int k = 0; k < 3; ++k) cut.v[k] = dvec3(mesh.vertex(t, k));
    cut.plane = planes[t];
    const dvec3 centroid = (cut.v[0] + cut.v[1] + cut.v[2]) / 3.0;
    const double rho =
        std::max({glm::length(cut.v[0] - centroid), glm::length(cut.v[1] - centroid),
                  glm::length(cut.v[2] - centroid)});
    cut.region_count = circumscribedPyramid(c, r, centroid, rho, cut.region.data());
    out.push_back(cut);
  }
}

// Where mesh m's edge i is a potential silhouette, appends it and its triangles to `part`.
void appendIfPotential(const Mesh& mesh, const EdgeAdjacency& adjacency,
                       const std::vector<dvec4>& planes, const std::vector<int8_t>& winding,
                       const TriangleSides& sides, size_t i, uint32_t first_id,
                       uint32_t first_edge, const dvec3& c, PotentialEdges& part) {
  const Edge& edge = adjacency.edges[i];
  // Decided from the per-triangle bytes first: most edges are not potential.
  int count = 0, cutting = 0, centre_sides = 0;
  for (uint32_t u = 0; u < edge.use_count; ++u) {
    const uint32_t t = adjacency.uses[edge.first_use + u].triangle;
    if (planes[t] == dvec4(0.0)) continue;  // zero area: blocks no ray
    ++count;
    cutting += sides.cuts[t];
    centre_sides -= winding[edge.first_use + u] * sides.centre_side[t];
  }
  if (count == 0) return;  // no triangle with an area
  // Two triangles on opposite sides seen from the centre, and neither plane near the light:
  // never a silhouette from any point of it.
  if (count == 2 && cutting == 0 && centre_sides == 0) return;
  const dvec3 a(mesh.positions[edge.v0]), b(mesh.positions[edge.v1]);
  const uint32_t first = uint32_t(part.triangles.size());
  for (uint32_t u = 0; u < edge.use_count; ++u) {
    const uint32_t t = adjacency.uses[edge.first_use + u].triangle;
    const dvec4& plane = planes[t];
    if (plane == dvec4(0.0)) continue;
    part.triangles.push_back(EdgeTriangle{first_id + t, glm::dot(dvec3(plane), c) + plane.w > 0.0,
                                          sides.cuts[t] != 0, winding[edge.first_use + u],
                                          oppositeVertex(mesh, t, edge.v0, edge.v1), dvec3(plane),
                                          plane.w});
  }
  part.edges.push_back(PotentialEdge{a, b, first, uint32_t(count), first_edge + uint32_t(i),
                                     glm::cross(a - c, b - c)});
}

}  // namespace

PotentialEdges potentialEdges(const Scene& scene, const EdgeGeometry& geometry,
                              const Light& light) {
  const dvec3 c(light.center);
  const double r = light.radius;
  PotentialEdges out;
  uint32_t first_id = 0, first_edge = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const EdgeAdjacency& adjacency = scene.adjacency[m];
    const std::vector<dvec4>& planes = geometry.planes[m];
    const std::vector<int8_t>& winding = geometry.winding[m];
    out.scene_edges += adjacency.edges.size();
    const TriangleSides sides = triangleSides(mesh, planes, c, r);
    appendCuttingTriangles(mesh, planes, sides, first_id, c, r, out.cutting);
    const size_t edge_count = adjacency.edges.size();
    const size_t chunks = (edge_count + kEdgesPerItem - 1) / kEdgesPerItem;
    std::vector<PotentialEdges> parts(chunks);
    parallelFor(chunks, [&](size_t chunk) {
      const size_t end = std::min(edge_count, (chunk + 1) * kEdgesPerItem);
      for (size_t i = chunk * kEdgesPerItem; i < end; ++i)
        appendIfPotential(mesh, adjacency, planes, winding, sides, i, first_id, first_edge, c,
                          parts[chunk]);
    });
    for (PotentialEdges& part : parts) {
      const uint32_t base = uint32_t(out.triangles.size());
      for (PotentialEdge e : part.edges) {
        e.first_triangle += base;
        out.edges.push_back(e);
      }
      out.triangles.insert(out.triangles.end(), part.triangles.begin(), part.triangles.end());
    }
    first_id += uint32_t(mesh.triangleCount());
    first_edge += uint32_t(edge_count);
  }
  return out;
}

}  // namespace penumbra
