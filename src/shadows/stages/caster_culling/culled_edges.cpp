#include "shadows/stages/caster_culling/culled_edges.h"

#include <algorithm>

namespace penumbra {
namespace {

// The mesh holding global triangle `id` (Scene::triangle_offsets: each mesh's first id).
size_t meshOfTriangle(const Scene& scene, uint32_t id) {
  const auto& offsets = scene.triangle_offsets;
  return size_t(std::upper_bound(offsets.begin(), offsets.end(), id) - offsets.begin()) - 1;
}

}  // namespace

PotentialEdges withoutCulledCasters(const PotentialEdges& edges, const Scene& scene,
                                    const CasterCulling& culling) {
  PotentialEdges out;
  out.scene_edges = edges.scene_edges;
  out.edges.reserve(edges.edges.size());
  out.triangles.reserve(edges.triangles.size());
  for (const PotentialEdge& edge : edges.edges) {
    // Every potential edge has a triangle (potential_edges.cpp leaves out the others).
    if (!culling.mayShadow(meshOfTriangle(scene, edges.triangles[edge.first_triangle].id)))
      continue;
    PotentialEdge kept = edge;
    kept.first_triangle = uint32_t(out.triangles.size());
    out.triangles.insert(out.triangles.end(), edges.triangles.begin() + edge.first_triangle,
                         edges.triangles.begin() + edge.first_triangle + edge.triangle_count);
    out.edges.push_back(kept);
  }
  for (const CuttingTriangle& cut : edges.cutting)
    if (culling.mayShadow(meshOfTriangle(scene, cut.id))) out.cutting.push_back(cut);
  return out;
}

}  // namespace penumbra
