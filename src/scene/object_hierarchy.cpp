#include "scene/object_hierarchy.h"

#include <algorithm>
#include <numeric>

#include "core/parallel.h"

namespace penumbra {
namespace {

int longestAxis(const Bounds3& b) {
  const vec3 e = b.extent();
  return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
}

// Cuts `ids` (a mesh's triangle indices, [begin, end)) at the median of their centroids along
// the longest axis of the centroids' box until every piece holds at most kClusterTriangles;
// appends the pieces' ranges to `pieces`.
void splitTriangles(const std::vector<vec3>& centroids, std::vector<uint32_t>& ids, size_t begin,
                    size_t end, std::vector<std::pair<size_t, size_t>>& pieces) {
  if (end - begin <= kClusterTriangles) {
    pieces.emplace_back(begin, end);
    return;
  }
  Bounds3 box;
  for (size_t i = begin; i < end; ++i) box.extend(centroids[ids[i]]);
  const int axis = longestAxis(box);
  const size_t middle = begin + (end - begin) / 2;
  std::nth_element(ids.begin() + long(begin), ids.begin() + long(middle), ids.begin() + long(end),
                   [&](uint32_t a, uint32_t b) {
                     // Ties by index: the split, and so the clusters, do not depend on the
                     // library's nth_element.
                     const float ca = centroids[a][axis], cb = centroids[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  splitTriangles(centroids, ids, begin, middle, pieces);
  splitTriangles(centroids, ids, middle, end, pieces);
}

// One mesh's clusters: their triangles (local indices, each cluster's ascending) and ranges.
struct MeshClusters {
  std::vector<uint32_t> ids;
  std::vector<std::pair<size_t, size_t>> pieces;
};

MeshClusters clusterMesh(const Mesh& mesh) {
  MeshClusters out;
  const size_t n = mesh.triangleCount();
  out.ids.resize(n);
  std::iota(out.ids.begin(), out.ids.end(), 0u);
  if (n <= kClusterTriangles) {
    if (n > 0) out.pieces.emplace_back(0, n);
    return out;
  }
  std::vector<vec3> centroids(n);
  for (size_t t = 0; t < n; ++t)
    centroids[t] = (mesh.vertex(t, 0) + mesh.vertex(t, 1) + mesh.vertex(t, 2)) / 3.0f;
  splitTriangles(centroids, out.ids, 0, n, out.pieces);
  for (const auto& [b, e] : out.pieces)
    std::sort(out.ids.begin() + long(b), out.ids.begin() + long(e));
  return out;
}

// Builds the subtree over clusters order[begin, end) into nodes[index] (median split of the
// clusters' box centres along the longest axis of those centres).
void buildNode(ObjectHierarchy& h, std::vector<uint32_t>& order, size_t begin, size_t end,
               size_t index) {
  Bounds3 box, centres;
  for (size_t i = begin; i < end; ++i) {
    box.extend(h.clusters[order[i]].bounds);
    centres.extend(h.clusters[order[i]].bounds.center());
  }
  h.nodes[index].bounds = box;
  if (end - begin == 1) {
    h.nodes[index].first = order[begin];
    h.nodes[index].count = 1;
    return;
  }
  const int axis = longestAxis(centres);
  const size_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + long(begin), order.begin() + long(middle),
                   order.begin() + long(end), [&](uint32_t a, uint32_t b) {
                     const float ca = h.clusters[a].bounds.center()[axis];
                     const float cb = h.clusters[b].bounds.center()[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const size_t children = h.nodes.size();
  h.nodes.emplace_back();
  h.nodes.emplace_back();
  h.nodes[index].first = uint32_t(children);
  h.nodes[index].count = 0;
  buildNode(h, order, begin, middle, children);
  buildNode(h, order, middle, end, children + 1);
}

}  // namespace

ObjectHierarchy buildObjectHierarchy(const Scene& scene) {
  ObjectHierarchy h;
  const size_t meshes = scene.meshes.size();
  std::vector<MeshClusters> per_mesh(meshes);
  parallelFor(meshes, [&](size_t m) { per_mesh[m] = clusterMesh(scene.meshes[m]); });

  const size_t triangle_count = scene.triangleCount();
  h.triangles.reserve(triangle_count);
  h.cluster_of.resize(triangle_count);
  h.vertex_indices.resize(triangle_count * 3);
  uint32_t first_triangle = 0, first_vertex = 0;
  for (size_t m = 0; m < meshes; ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (const auto& [b, e] : per_mesh[m].pieces) {
      ObjectCluster c;
      c.mesh = uint32_t(m);
      c.first = uint32_t(h.triangles.size());
      c.count = uint32_t(e - b);
      for (size_t i = b; i < e; ++i) {
        const uint32_t t = per_mesh[m].ids[i];
        for (int k = 0; k < 3; ++k) c.bounds.extend(mesh.vertex(t, k));
        h.triangles.push_back(first_triangle + t);
        h.cluster_of[first_triangle + t] = uint32_t(h.clusters.size());
      }
      h.clusters.push_back(c);
    }
    const size_t n = mesh.triangleCount();
    for (size_t i = 0; i < n * 3; ++i)
      h.vertex_indices[size_t(first_triangle) * 3 + i] = first_vertex + mesh.indices[i];
    first_triangle += uint32_t(n);
    first_vertex += uint32_t(mesh.positions.size());
  }
  if (h.clusters.empty()) return h;
  std::vector<uint32_t> order(h.clusters.size());
  std::iota(order.begin(), order.end(), 0u);
  h.nodes.reserve(2 * h.clusters.size());
  h.nodes.emplace_back();
  buildNode(h, order, 0, order.size(), 0);
  return h;
}

}  // namespace penumbra
