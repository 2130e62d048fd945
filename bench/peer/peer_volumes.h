#pragma once
// Per-frame shadow volume index lists for the llvmpipe peer (Everitt & Kilgard 2002, z-fail with
// caps, volumes extruded to infinity by the vertex shader).
//
// The volume vertex buffer holds every welded position of every mesh twice: first all of them
// with w = 1, then all of them again with w = 0. The vertex shader moves a w = 0 vertex to the
// point at infinity in the direction away from the light, so a frame only uploads indices.
//
// Two caster modes:
// - two-sided: exactly our renderer's volumes (shadows/stages/silhouettes/silhouette.h): every
//   triangle not edge-on casts, facing-away ones flipped; a side quad of multiplicity m is drawn
//   |m| times, because the stencil counts in steps of one and a volume whose sides undercount
//   their weight is not closed (a lit point whose eye ray leaves through such a side would read
//   -1 and be shadowed).
// - one-sided: the classic Everitt-Kilgard volume, only light-facing triangles cast. For a closed
//   mesh with the light outside it, every light-to-point segment crosses as many facing-away
//   triangles as light-facing ones, so the count is exactly half of the two-sided one: same
//   shadow, half the caps and sides. Open meshes, and closed ones whose bounding box holds the
//   light (where the halving fails), keep the two-sided volumes.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "scene/scene.h"
#include "shadows/stages/silhouettes/silhouette.h"

namespace penumbra {

enum class CasterMode { kOneSided, kTwoSided };

struct VolumeIndices {
  // Triangles whose counter-clockwise side faces out of the shadow: side quads, caps cast as
  // wound. Drawn with glFrontFace(GL_CCW).
  std::vector<uint32_t> outward;
  // Caps of triangles cast flipped (facing away from the light), kept in the mesh's own vertex
  // order so a light cap rasterizes to bit-identical depth as the eye pass drew it: drawn with
  // glFrontFace(GL_CW) instead of reordering the vertices.
  std::vector<uint32_t> flipped;
  uint64_t silhouette_edges = 0;  // findSilhouette's edges (non-zero multiplicity)
  uint64_t side_quads = 0;        // quads drawn, counting repeats
  uint64_t cap_triangles = 0;     // light caps plus dark caps

  void clear() {
    outward.clear();
    flipped.clear();
    silhouette_edges = side_quads = cap_triangles = 0;
  }
  size_t triangleCount() const { return (outward.size() + flipped.size()) / 3; }
};

// Per-mesh data fixed for a static scene.
struct VolumeMesh {
  uint32_t base = 0;  // index of the mesh's first welded position in the volume buffer
  bool closed = false;
  Bounds3 bounds;
  // Undirected edge (v0 << 32 | v1) -> index into EdgeAdjacency::edges, for the rare odd
  // multiplicity in one-sided mode (only next to triangles exactly edge-on to the light).
  std::unordered_map<uint64_t, uint32_t> edge_index;
};

std::vector<VolumeMesh> prepareVolumeMeshes(const Scene& scene);
// The volume vertex buffer's content: xyzw per vertex, all w = 1 copies then all w = 0 copies.
std::vector<float> volumeVertices(const Scene& scene);
uint32_t volumeVertexCount(const Scene& scene);  // the w = 1 half

// Appends one mesh's volume from `silhouette` (findSilhouette from `light`). `far_offset` is
// volumeVertexCount(scene): the index distance from a w = 1 vertex to its w = 0 copy.
void appendVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const VolumeMesh& info,
                  const Silhouette& silhouette, const vec3& light, CasterMode mode,
                  uint32_t far_offset, VolumeIndices& out);

}  // namespace penumbra
