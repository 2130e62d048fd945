#include "shadows/exact/potential_edges.h"

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

PotentialEdges potentialEdges(const Scene& scene, const Light& light) {
  const dvec3 c(light.center);
  const double r = light.radius;
  PotentialEdges out;
  uint32_t first_id = 0, first_edge = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const EdgeAdjacency& adjacency = scene.adjacency[m];
    out.scene_edges += adjacency.edges.size();
    // Planes of the mesh's triangles, once (an edge asks for two of them).
    std::vector<dvec4> planes(mesh.triangleCount());
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
    // Planes that cut the ball (with slack: a triangle counted sample by sample is exact too).
    std::vector<uint8_t> cuts(mesh.triangleCount(), 0);
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      const dvec4& plane = planes[t];
      if (plane == dvec4(0.0)) continue;
      const double scale = glm::length(dvec3(mesh.vertex(t, 0)) - c) + r;
      if (std::fabs(glm::dot(dvec3(plane), c) + plane.w) <= r * (1.0 + kSlack) + kSlack * scale) {
        cuts[t] = 1;
        CuttingTriangle cut;
        cut.id = first_id + uint32_t(t);
        for (int k = 0; k < 3; ++k) cut.v[k] = dvec3(mesh.vertex(t, k));
        cut.plane = plane;
        const dvec3 centroid = (cut.v[0] + cut.v[1] + cut.v[2]) / 3.0;
        const double rho =
            std::max({glm::length(cut.v[0] - centroid), glm::length(cut.v[1] - centroid),
                      glm::length(cut.v[2] - centroid)});
        cut.region_count = circumscribedPyramid(c, r, centroid, rho, cut.region.data());
        out.cutting.push_back(cut);
      }
    }
    const size_t edge_count = adjacency.edges.size();
    const size_t chunks = (edge_count + kEdgesPerItem - 1) / kEdgesPerItem;
    std::vector<PotentialEdges> parts(chunks);
    parallelFor(chunks, [&](size_t chunk) {
      PotentialEdges& part = parts[chunk];
      const size_t end = std::min(edge_count, (chunk + 1) * kEdgesPerItem);
      for (size_t i = chunk * kEdgesPerItem; i < end; ++i) {
        const Edge& edge = adjacency.edges[i];
        const dvec3 a(mesh.positions[edge.v0]), b(mesh.positions[edge.v1]);
        const size_t first = part.triangles.size();
        int cutting = 0, centre_sides = 0;
        for (uint32_t u = 0; u < edge.use_count; ++u) {
          const uint32_t t = adjacency.uses[edge.first_use + u].triangle;
          const dvec4& plane = planes[t];
          if (plane == dvec4(0.0)) continue;  // zero area: blocks no ray
          dvec3 opposite(0.0);
          for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[t * 3 + size_t(k)];
            if (v != edge.v0 && v != edge.v1) opposite = dvec3(mesh.positions[v]);
          }
          const dvec3 normal(plane);
          const double at_centre = glm::dot(normal, c) + plane.w;
          // Side of the triangle seen from the centre (EdgeTriangle).
          const int8_t winding =
              glm::dot(normal, glm::cross(b - a, opposite - a)) >= 0.0 ? int8_t(1) : int8_t(-1);
          cutting += cuts[t];
          centre_sides -= winding * sign(at_centre);
          part.triangles.push_back(EdgeTriangle{first_id + t, at_centre > 0.0, cuts[t] != 0,
                                                winding, opposite, normal, plane.w});
        }
        const size_t count = part.triangles.size() - first;
        if (count == 0) continue;  // no triangle with an area
        // Two triangles on opposite sides seen from the centre, and neither plane near the
        // light: never a silhouette from any point of it.
        const bool potential = count != 2 || cutting > 0 || centre_sides != 0;
        if (!potential) {
          part.triangles.resize(first);
          continue;
        }
        part.edges.push_back(PotentialEdge{a, b, uint32_t(first), uint32_t(count),
                                           first_edge + uint32_t(i), glm::cross(a - c, b - c)});
      }
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
