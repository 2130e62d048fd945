#include "shadows/stages/potential_edges/potential_edges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"

namespace penumbra {
namespace {

constexpr size_t kEdgesPerItem = 2048;  // edges (or triangles) per work item
static_assert(kEdgesPerItem % kEdgesPerCluster == 0 && kEdgesPerItem % kTrianglesPerCluster == 0,
              "a work item holds whole clusters");

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

int clusterSide(const PlaneCluster& cluster, const dvec3& c, double r) {
  if (!cluster.usable) return 0;
  const dvec3 d = c - cluster.centre;
  const double distance = glm::length(d);
  const double along = glm::dot(cluster.axis, d);                // |d| cos(theta)
  const double across = glm::length(glm::cross(cluster.axis, d));  // |d| sin(theta)
  // n . d over the unit normals n of the cone: at least |d| cos(theta + half), at most
  // |d| cos(max(theta - half, 0)); each used only where it has the sign asked for, where the
  // angle sum lies within [0, pi].
  const double low = along * cluster.cos_half - across * cluster.sin_half;
  const double high = along >= distance * cluster.cos_half
                          ? distance
                          : along * cluster.cos_half + across * cluster.sin_half;
  // Each triangle's test: |n . c + w| <= r (1 + kSlack) + kSlack (|v0 - c| + r) is "cuts", with
  // |v0 - c| <= distance + vertex_reach. The margin (1e-7 of every length involved) is far
  // above the rounding of both tests and far below what separates a cluster from the light.
  const double threshold = r * (1.0 + kSlack) + kSlack * (distance + cluster.vertex_reach + r);
  const double margin = 1e-7 * (glm::length(c) + 2.0 * glm::length(cluster.centre) +
                                cluster.plane_reach + cluster.vertex_reach + r + distance);
  if (low - cluster.plane_reach > threshold + margin) return 1;
  if (high + cluster.plane_reach < -(threshold + margin)) return -1;
  return 0;
}

namespace {

// Bounds over the planes of triangles `ids` of `mesh` (PlaneCluster); not usable when one has
// no area or their normals spread too far for the bounds to decide anything.
PlaneCluster boundPlanes(const Mesh& mesh, const std::vector<dvec4>& planes,
                         const std::vector<uint32_t>& ids) {
  PlaneCluster cluster;
  if (ids.empty()) return cluster;
  dvec3 sum(0.0), lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const uint32_t t : ids) {
    if (planes[t] == dvec4(0.0)) return cluster;
    sum += dvec3(planes[t]);
    for (int k = 0; k < 3; ++k) {
      const dvec3 v(mesh.vertex(t, k));
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  const double length = glm::length(sum);
  if (!(length > 0.0) || !std::isfinite(length)) return cluster;
  cluster.axis = sum / length;
  cluster.centre = (lo + hi) * 0.5;
  // The box holds every vertex: none lies farther from its centre than half its diagonal.
  cluster.vertex_reach = 0.5 * glm::length(hi - lo);
  double cos_min = 1.0;
  for (const uint32_t t : ids) {
    const dvec4& plane = planes[t];
    cos_min = std::min(cos_min, glm::dot(cluster.axis, dvec3(plane)));
    cluster.plane_reach = std::max(
        cluster.plane_reach, std::fabs(glm::dot(dvec3(plane), cluster.centre) + plane.w));
  }
  // Widened past the rounding of the dot products and of acos near 0.
  const double half = std::acos(std::clamp(cos_min - 1e-12, -1.0, 1.0)) + 1e-7;
  if (!(half < 1.5)) return cluster;  // about a hemisphere: nothing to decide
  cluster.cos_half = std::cos(half);
  cluster.sin_half = std::sin(half);
  cluster.usable = std::isfinite(cluster.plane_reach) && std::isfinite(cluster.vertex_reach);
  return cluster;
}

// The clusters of consecutive edges of a mesh: usable only where every edge is one of two
// triangles wound opposite ways along it (then, with the centre on the same side of both and
// neither plane cutting the ball, the edge is no potential silhouette).
std::vector<PlaneCluster> edgeClusters(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                       const std::vector<dvec4>& planes,
                                       const std::vector<int8_t>& winding) {
  const size_t count = (adjacency.edges.size() + kEdgesPerCluster - 1) / kEdgesPerCluster;
  std::vector<PlaneCluster> clusters(count);
  constexpr size_t kClustersPerItem = kEdgesPerItem / kEdgesPerCluster;
  parallelFor((count + kClustersPerItem - 1) / kClustersPerItem, [&](size_t chunk) {
    std::vector<uint32_t> ids;
    const size_t end = std::min(count, (chunk + 1) * kClustersPerItem);
    for (size_t k = chunk * kClustersPerItem; k < end; ++k) {
      ids.clear();
      const size_t last = std::min(adjacency.edges.size(), (k + 1) * kEdgesPerCluster);
      bool simple = true;
      for (size_t i = k * kEdgesPerCluster; i < last; ++i) {
        const Edge& edge = adjacency.edges[i];
        simple = edge.use_count == 2 &&
                 winding[edge.first_use] == -winding[edge.first_use + 1];
        if (!simple) break;
        ids.push_back(adjacency.uses[edge.first_use].triangle);
        ids.push_back(adjacency.uses[edge.first_use + 1].triangle);
      }
      if (simple) clusters[k] = boundPlanes(mesh, planes, ids);
    }
  });
  return clusters;
}

std::vector<PlaneCluster> triangleClusters(const Mesh& mesh, const std::vector<dvec4>& planes) {
  const size_t count = (mesh.triangleCount() + kTrianglesPerCluster - 1) / kTrianglesPerCluster;
  std::vector<PlaneCluster> clusters(count);
  constexpr size_t kClustersPerItem = kEdgesPerItem / kTrianglesPerCluster;
  parallelFor((count + kClustersPerItem - 1) / kClustersPerItem, [&](size_t chunk) {
    std::vector<uint32_t> ids;
    const size_t end = std::min(count, (chunk + 1) * kClustersPerItem);
    for (size_t k = chunk * kClustersPerItem; k < end; ++k) {
      ids.clear();
      const size_t last = std::min(mesh.triangleCount(), (k + 1) * kTrianglesPerCluster);
      for (size_t t = k * kTrianglesPerCluster; t < last; ++t) ids.push_back(uint32_t(t));
      clusters[k] = boundPlanes(mesh, planes, ids);
    }
  });
  return clusters;
}

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
  out.edge_clusters.resize(scene.meshes.size());
  out.triangle_clusters.resize(scene.meshes.size());
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
    out.edge_clusters[m] = edgeClusters(mesh, adjacency, planes, winding);
    out.triangle_clusters[m] = triangleClusters(mesh, planes);
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
  std::vector<uint8_t> area;  // 1: the triangle has an area (a plane); the edges read this byte
};
// A cluster the light sees wholly from one side (clusterSide) takes that side for every
// triangle, none cutting the ball, without evaluating their planes.
TriangleSides triangleSides(const Mesh& mesh, const std::vector<dvec4>& planes,
                            const std::vector<PlaneCluster>& clusters, const dvec3& c, double r) {
  TriangleSides sides;
  sides.centre_side.assign(mesh.triangleCount(), 0);
  sides.cuts.assign(mesh.triangleCount(), 0);
  sides.area.assign(mesh.triangleCount(), 0);
  parallelFor((mesh.triangleCount() + kEdgesPerItem - 1) / kEdgesPerItem, [&](size_t chunk) {
    const size_t end = std::min(mesh.triangleCount(), (chunk + 1) * kEdgesPerItem);
    for (size_t first = chunk * kEdgesPerItem; first < end; first += kTrianglesPerCluster) {
      const size_t last = std::min(end, first + kTrianglesPerCluster);
      const size_t k = first / kTrianglesPerCluster;
      const int side = k < clusters.size() ? clusterSide(clusters[k], c, r) : 0;
      if (side != 0) {
        // A usable cluster has no triangle without an area.
        std::fill(sides.centre_side.begin() + ptrdiff_t(first),
                  sides.centre_side.begin() + ptrdiff_t(last), int8_t(side));
        std::fill(sides.area.begin() + ptrdiff_t(first), sides.area.begin() + ptrdiff_t(last),
                  uint8_t(1));
        continue;
      }
      for (size_t t = first; t < last; ++t) {
        const dvec4& plane = planes[t];
        if (plane == dvec4(0.0)) continue;
        sides.area[t] = 1;
        const double at_centre = glm::dot(dvec3(plane), c) + plane.w;
        sides.centre_side[t] = int8_t(sign(at_centre));
        const double scale = glm::length(dvec3(mesh.vertex(t, 0)) - c) + r;
        sides.cuts[t] = std::fabs(at_centre) <= r * (1.0 + kSlack) + kSlack * scale;
      }
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
    if (!sides.area[t]) continue;  // zero area: blocks no ray
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

// The work items' edges and triangles appended in item order: sized once and copied in
// parallel (grown item by item, the arrays were copied as they doubled, and a first frame
// faulted their pages in on one thread).
void appendParts(const std::vector<PotentialEdges>& parts, PotentialEdges& out) {
  std::vector<size_t> edge_at(parts.size() + 1, out.edges.size());
  std::vector<size_t> triangle_at(parts.size() + 1, out.triangles.size());
  for (size_t k = 0; k < parts.size(); ++k) {
    edge_at[k + 1] = edge_at[k] + parts[k].edges.size();
    triangle_at[k + 1] = triangle_at[k] + parts[k].triangles.size();
    out.skipped_edges += parts[k].skipped_edges;
  }
  out.edges.resize(edge_at.back());
  out.triangles.resize(triangle_at.back());
  parallelFor(parts.size(), [&](size_t k) {
    const uint32_t base = uint32_t(triangle_at[k]);
    for (size_t i = 0; i < parts[k].edges.size(); ++i) {
      PotentialEdge e = parts[k].edges[i];
      e.first_triangle += base;
      out.edges[edge_at[k] + i] = e;
    }
    std::copy(parts[k].triangles.begin(), parts[k].triangles.end(),
              out.triangles.begin() + ptrdiff_t(triangle_at[k]));
  });
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
    static const std::vector<PlaneCluster> kNoClusters;
    const std::vector<PlaneCluster>& edge_clusters =
        m < geometry.edge_clusters.size() ? geometry.edge_clusters[m] : kNoClusters;
    const TriangleSides sides = triangleSides(
        mesh, planes,
        m < geometry.triangle_clusters.size() ? geometry.triangle_clusters[m] : kNoClusters, c,
        r);
    appendCuttingTriangles(mesh, planes, sides, first_id, c, r, out.cutting);
    const size_t edge_count = adjacency.edges.size();
    const size_t chunks = (edge_count + kEdgesPerItem - 1) / kEdgesPerItem;
    std::vector<PotentialEdges> parts(chunks);
    parallelFor(chunks, [&](size_t chunk) {
      const size_t end = std::min(edge_count, (chunk + 1) * kEdgesPerItem);
      for (size_t first = chunk * kEdgesPerItem; first < end; first += kEdgesPerCluster) {
        const size_t last = std::min(end, first + kEdgesPerCluster);
        const size_t k = first / kEdgesPerCluster;
        if (k < edge_clusters.size() && clusterSide(edge_clusters[k], c, r) != 0) {
          parts[chunk].skipped_edges += last - first;
          continue;
        }
        for (size_t i = first; i < last; ++i)
          appendIfPotential(mesh, adjacency, planes, winding, sides, i, first_id, first_edge, c,
                            parts[chunk]);
      }
    });
    appendParts(parts, out);
    first_id += uint32_t(mesh.triangleCount());
    first_edge += uint32_t(edge_count);
  }
  return out;
}

}  // namespace penumbra
