#pragma once
// The shadow volumes of one point light, one closed volume per caster mesh, set up for the
// rasterizer and kept apart: the per-volume passes (depth bounds, thesis section 2.2; hierarchical
// shadow volumes, section 4.3) need to know where one volume ends and the next begins, which the
// per-pixel stencil (shadows/stages/stencil/shadow_stencil.cpp) never does.
#include <cstdint>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/volume_options.h"

namespace penumbra {

// A silhouette edge on screen, between its two finite vertices projected (pixels, unsnapped),
// for the z-pass volumes (tiled_volume_stencil.cpp says why). `anywhere`: an end lies behind
// the near plane, so the drawn edge is a clipped piece of a line not worked out here: it is
// taken to cross every tile.
struct ScreenSegment {
  double x0, y0, x1, y1;
  bool anywhere;
};

struct ShadowVolumeSet {
  // Every volume's triangles, volume after volume, each volume's in the order the per-pixel
  // stencil draws them: side quads of its silhouette edges, then with z-fail its caps. In a
  // z-pass volume, the quad triangle holding the silhouette edge (its first) has owners[0] set
  // to the edge's index in `silhouettes`, and every triangle's owners[1] is its volume (the
  // owners are not used otherwise here; fan pieces of a clipped triangle keep them).
  std::vector<SetupTriangle> triangles;
  // Volume v owns triangles [begin[v], begin[v + 1]).
  std::vector<uint32_t> begin;
  std::vector<uint8_t> zfail;
  // Volumes that may contain part of the near-plane rectangle, so the eye may be inside them
  // (caster_volume.h: mayContainNearPlane). Then a point nearer than all of the volume is inside
  // it too, and a z-pass volume is open on screen: no tile of it can be decided by one sample.
  std::vector<uint8_t> may_contain_eye;
  // Per volume, the depth range of its drawn triangles' vertices after clipping (reversed-Z):
  // the depth bounds of thesis section 2.2 (Figure 2.3).
  std::vector<float> depth_min, depth_max;
  std::vector<ScreenSegment> silhouettes;  // of the z-pass volumes
  // Per volume, its faces that set-up dropped on screen (VanishedPiece: seen edge-on, with the
  // eye in their plane): volume v's are vanished[vanished_begin[v] .. vanished_begin[v + 1]).
  // Such a face draws nothing, so no triangle test finds it crossing a tile, yet the count
  // changes across it: the tiles it reaches are drawn per pixel (tiled_volume_stencil.cpp).
  std::vector<VanishedPiece> vanished;
  std::vector<uint32_t> vanished_begin;

  size_t volumeCount() const { return zfail.size(); }
};

// Files set-up's vanished pieces of `polygons` (the set's input, owners[1] of each its volume;
// volume 0 when the polygons have no owners) under their volumes, in set.vanished and
// set.vanished_begin (set.volumeCount() volumes).
void indexVanishedPieces(const ClipTriangles& polygons, std::vector<VanishedPiece> pieces,
                         ShadowVolumeSet& set);

// Builds the volumes of every scene mesh for a point light at `centre`; fills the pass
// "silhouette" and the counters silhouette_edges and triangles of `stats`. With
// `silhouette_layer`, draws the silhouette edges into it (kSilhouetteEdgesLayer). With
// `caster_culling`, a mesh it culls keeps an empty volume (no polygon).
ShadowVolumeSet buildShadowVolumes(const Scene& scene, const vec3& centre, const View& view,
                                   const EyeBuffers& eye, VolumeMode mode, Stats& stats,
                                   Image<float>* silhouette_layer = nullptr,
                                   const CasterCulling* caster_culling = nullptr);

}  // namespace penumbra
