#include "peer_volumes.h"

#include <cstdlib>

#include "core/error.h"

namespace penumbra {
namespace {

uint64_t edgeKey(uint32_t v0, uint32_t v1) { return (uint64_t(v0) << 32) | v1; }

bool boxHoldsPoint(const Bounds3& box, const vec3& p) {
  // A margin so that a light on (or a rounding away from) a closed mesh's surface also takes the
  // always-correct two-sided path.
  const vec3 margin = 1e-4f * (box.extent() + vec3(1.0f));
  return glm::all(glm::greaterThanEqual(p, box.min - margin)) &&
         glm::all(glm::lessThanEqual(p, box.max + margin));
}

void pushTriangle(std::vector<uint32_t>& list, uint32_t a, uint32_t b, uint32_t c) {
  list.push_back(a);
  list.push_back(b);
  list.push_back(c);
}

}  // namespace

std::vector<VolumeMesh> prepareVolumeMeshes(const Scene& scene) {
  PENUMBRA_CHECK(scene.adjacency.size() == scene.meshes.size(),
                 "llvmpipe peer: scene '{}' is not finalized (no edge adjacency)", scene.name);
  std::vector<VolumeMesh> out(scene.meshes.size());
  uint32_t base = 0;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    VolumeMesh& info = out[i];
    info.base = base;
    info.closed = mesh.closed;
    info.bounds = mesh.bounds();
    if (mesh.closed) {
      const EdgeAdjacency& adjacency = scene.adjacency[i];
      info.edge_index.reserve(adjacency.edges.size());
      for (size_t e = 0; e < adjacency.edges.size(); ++e)
        info.edge_index.emplace(edgeKey(adjacency.edges[e].v0, adjacency.edges[e].v1), uint32_t(e));
    }
    base += uint32_t(mesh.positions.size());
  }
  return out;
}

uint32_t volumeVertexCount(const Scene& scene) {
  uint64_t n = 0;
  for (const Mesh& mesh : scene.meshes) n += mesh.positions.size();
  PENUMBRA_CHECK(2 * n < (uint64_t(1) << 32), "llvmpipe peer: {} vertices overflow 32-bit indices",
                 n);
  return uint32_t(n);
}

std::vector<float> volumeVertices(const Scene& scene) {
  std::vector<float> out;
  out.reserve(size_t(volumeVertexCount(scene)) * 8);
  for (float w : {1.0f, 0.0f}) {
    for (const Mesh& mesh : scene.meshes) {
      for (const vec3& p : mesh.positions) {
        out.push_back(p.x);
        out.push_back(p.y);
        out.push_back(p.z);
        out.push_back(w);
      }
    }
  }
  return out;
}

void appendVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const VolumeMesh& info,
                  const Silhouette& silhouette, const vec3& light, CasterMode mode,
                  uint32_t far_offset, VolumeIndices& out) {
  const bool one_sided =
      mode == CasterMode::kOneSided && info.closed && !boxHoldsPoint(info.bounds, light);
  const uint32_t base = info.base;
  const uint32_t far = base + far_offset;
  const std::vector<int8_t>& orientation = silhouette.orientation;

  for (size_t t = 0; t < orientation.size(); ++t) {
    const int o = orientation[t];
    if (o == 0 || (one_sided && o < 0)) continue;
    const uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                   c = mesh.indices[3 * t + 2];
    if (o > 0) {
      pushTriangle(out.outward, base + a, base + b, base + c);
      pushTriangle(out.outward, far + c, far + b, far + a);
    } else {
      pushTriangle(out.flipped, base + a, base + b, base + c);
      pushTriangle(out.outward, far + a, far + b, far + c);
    }
    out.cap_triangles += 2;
  }

  out.silhouette_edges += silhouette.edges.size();
  for (const SilhouetteEdge& e : silhouette.edges) {
    int32_t m = e.multiplicity;
    if (one_sided) {
      if (m % 2 == 0) {
        m /= 2;
      } else {
        // Only next to a triangle exactly edge-on to the light: count the light-facing uses.
        const Edge& edge = adjacency.edges[info.edge_index.at(edgeKey(e.v0, e.v1))];
        m = 0;
        for (uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
          if (orientation[adjacency.uses[u].triangle] > 0) m += adjacency.uses[u].sign;
        }
      }
    }
    // The quad (v1, v0, v0 at infinity, v1 at infinity) faces out of the volume for m > 0.
    const uint32_t p = base + (m > 0 ? e.v1 : e.v0), q = base + (m > 0 ? e.v0 : e.v1);
    for (int32_t k = std::abs(m); k > 0; --k) {
      pushTriangle(out.outward, p, q, q + far_offset);
      pushTriangle(out.outward, p, q + far_offset, p + far_offset);
      ++out.side_quads;
    }
  }
}

}  // namespace penumbra
