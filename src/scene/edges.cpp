#include "scene/edges.h"

#include <algorithm>

#include "core/error.h"
#include "scene/repeated_triangles.h"

namespace penumbra {

namespace {

// One directed edge use, bucketed by its smaller vertex.
struct HalfEdge {
  uint32_t other;     // the larger vertex of the undirected edge
  uint32_t triangle;
  int8_t sign;
};

bool isDegenerateTriangle(const Mesh& mesh, size_t t) {
  const uint32_t* v = &mesh.indices[3 * t];
  return v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
}

// The directed edges of the non-degenerate triangles, bucketed by their smaller vertex by a
// counting sort (a CSR bucket per vertex: vertex v's are [bucket_start[v], bucket_start[v +
// 1])), in triangle order within a bucket.
std::vector<HalfEdge> bucketHalfEdges(const Mesh& mesh, std::vector<uint32_t>& bucket_start) {
  const size_t vertex_count = mesh.positions.size();
  const size_t triangle_count = mesh.triangleCount();
  bucket_start.assign(vertex_count + 1, 0);
  for (size_t t = 0; t < triangle_count; ++t) {
    if (isDegenerateTriangle(mesh, t)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = mesh.indices[3 * t + k];
      const uint32_t b = mesh.indices[3 * t + (k + 1) % 3];
      ++bucket_start[std::min(a, b) + 1];
    }
  }
  for (size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<HalfEdge> half_edges(bucket_start[vertex_count]);
  std::vector<uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
  for (size_t t = 0; t < triangle_count; ++t) {
    if (isDegenerateTriangle(mesh, t)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = mesh.indices[3 * t + k];
      const uint32_t b = mesh.indices[3 * t + (k + 1) % 3];
      const bool forward = a < b;
      half_edges[fill[forward ? a : b]++] =
          HalfEdge{forward ? b : a, uint32_t(t), int8_t(forward ? 1 : -1)};
    }
  }
  return half_edges;
}

// Sorts a bucket by the larger vertex. Buckets hold a vertex's edges to larger neighbours
// (about 3 on average); a stable sort keeps each edge's uses in triangle order.
void sortBucket(HalfEdge* begin, HalfEdge* end) {
  auto byOther = [](const HalfEdge& x, const HalfEdge& y) { return x.other < y.other; };
  if (end - begin <= 16) {
    for (HalfEdge* i = begin + 1; i < end; ++i) {  // insertion sort: stable, no allocation
      const HalfEdge h = *i;
      HalfEdge* j = i;
      for (; j != begin && byOther(h, *(j - 1)); --j) *j = *(j - 1);
      *j = h;
    }
  } else {
    std::stable_sort(begin, end, byOther);
  }
}

// The edges of vertex v's sorted bucket, one per run of equal larger vertices, with their uses
// and their class (open, non-manifold, inconsistently wound) counted.
void addBucketEdges(uint32_t v, HalfEdge* begin, HalfEdge* end, EdgeAdjacency& adjacency) {
  for (HalfEdge* run = begin; run != end;) {
    HalfEdge* run_end = run;
    while (run_end != end && run_end->other == run->other) ++run_end;
    Edge edge{v, run->other, uint32_t(adjacency.uses.size()), uint32_t(run_end - run)};
    int sign_sum = 0;
    for (HalfEdge* h = run; h != run_end; ++h) {
      adjacency.uses.push_back(EdgeUse{h->triangle, h->sign});
      sign_sum += h->sign;
    }
    if (edge.use_count == 1) {
      ++adjacency.open_edges;
    } else if (edge.use_count >= 3) {
      ++adjacency.non_manifold_edges;
    } else if (sign_sum != 0) {
      ++adjacency.inconsistent_edges;
    }
    adjacency.edges.push_back(edge);
    run = run_end;
  }
}

}  // namespace

EdgeAdjacency buildEdges(Mesh& mesh) {
  const size_t vertex_count = mesh.positions.size();
  const size_t triangle_count = mesh.triangleCount();
  PENUMBRA_CHECK(mesh.indices.size() % 3 == 0,
                 "mesh '{}': {} indices is not a whole number of triangles", mesh.name,
                 mesh.indices.size());
  PENUMBRA_CHECK(triangle_count < (size_t(1) << 31), "mesh '{}' has too many triangles ({})",
                 mesh.name, triangle_count);
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    PENUMBRA_CHECK(mesh.indices[i] < vertex_count,
                   "mesh '{}': triangle {} references vertex {} but the mesh has {} vertices",
                   mesh.name, i / 3, mesh.indices[i], vertex_count);
  }
  // Counting sort of the directed edges by their smaller vertex, then a sort by the larger
  // vertex inside each small bucket: linear time, and edges come out in (v0, v1) order with
  // their uses in triangle order, independent of any hashing.
  std::vector<uint32_t> bucket_start;
  std::vector<HalfEdge> half_edges = bucketHalfEdges(mesh, bucket_start);
  EdgeAdjacency adjacency;
  adjacency.uses.reserve(half_edges.size());
  adjacency.edges.reserve(half_edges.size() / 2 + 1);
  for (uint32_t v = 0; v < vertex_count; ++v) {
    HalfEdge* begin = half_edges.data() + bucket_start[v];
    HalfEdge* end = half_edges.data() + bucket_start[v + 1];
    sortBucket(begin, end);
    addBucketEdges(v, begin, end, adjacency);
  }
  mesh.closed = !adjacency.edges.empty() && adjacency.open_edges == 0 &&
                adjacency.non_manifold_edges == 0 && adjacency.inconsistent_edges == 0;
  adjacency.repeated = findRepeatedTriangles(mesh, adjacency);
  return adjacency;
}

}  // namespace penumbra
