#pragma once
// The hard shadow volumes' stencil drawn volume by volume, with one of two ways of drawing fewer
// pixels than the per-pixel passes (shadows/stages/stencil/shadow_stencil.cpp), both ending with
// the same stencil on every pixel that shows a surface:
//
// DepthBounds (thesis section 2.2, Figure 2.3; Nvidia's UltraShadow): each volume's depth range;
//   a volume triangle skips the tiles whose surfaces all lie farther than the volume, with
//   z-fail (no polygon is behind them), and those whose surfaces all lie nearer than it (no
//   polygon is in front: z-pass counts nothing; all are behind: z-fail counts the volume's
//   count at the eye, zero unless the eye may be inside, when the test is left out). Decided per
//   tile from its z-min and z-max, as the hardware's coarse depth test would; surviving tiles
//   draw every covered pixel. Far bounds reach infinity (depth 0) for every volume extruded
//   there, so the far test only helps volumes whose extrusion the guard band clipped.
// Hierarchical (thesis section 4.3, publication P2): per volume, each tile whose box (its pixel
//   centres times its surfaces' depth range) no triangle of the volume crosses
//   (tile_box_test.h) is inside or outside the volume as a whole: one sample pixel decides it,
//   from the triangles wholly in front of the box (z-pass) or wholly behind it (z-fail), by
//   coverage alone, and the result goes to a per-tile count (the coarse level of the two-level
//   stencil of section 4.3) that is added to the tile's surface pixels once. Only boundary
//   tiles are drawn per pixel. The thesis's argument holds for any box, so the volume is
//   tested against the 32x32 bin tile's box first: when no triangle crosses it, one sample
//   decides the whole bin tile, and its tiles are classified only when some triangle does.
#include "core/image.h"
#include "core/stats.h"
#include "raster/depth_buffer.h"
#include "shadows/hierarchical/volume_set.h"
#include "shadows/stages/silhouettes/facing_away.h"

namespace penumbra {

enum class VolumeCulling { DepthBounds, Hierarchical };

struct TiledVolumeStencilOptions {
  VolumeCulling culling = VolumeCulling::Hierarchical;
  // Tiles of 2^tile_level pixels, 2..5 (4x4 to the 32x32 bin tiles). 3, the thesis's 8x8, is
  // this struct's default; the `hierarchical-volume` technique's is 5 (hierarchical_technique.cpp
  // says why).
  int tile_level = 3;
  // Hierarchical: a volume with more than dense_limit triangles per 8x8 pixels of a bin tile
  // (16 x dense_limit in a 32x32 bin tile, whatever the tile size) is not classified triangle
  // by tile there (0: always classified, the thesis's way): one sample decides the bin tile if
  // every triangle's whole depth range lies in front of or behind its box, otherwise the volume
  // is drawn per pixel. A volume of many small polygons (a finely tessellated caster's
  // silhouette) crosses nearly every tile it reaches, and testing each (triangle, tile) pair
  // costs more than the pixels it could save; with tiles as large as the bin tile the tests stop
  // at the first triangle that crosses, which makes a higher limit pay (bench/README.md). The
  // stencil is the same either way.
  int dense_limit = 8;
  bool simd = true;
};

// Counts pixels_rasterized and z_reads (covered pixels drawn, plus the depth reads that find the
// surface range of tiles holding background), stencil_writes (per pixel, one per per-tile count
// written, and one per surface pixel a non-zero per-tile count is added to), tiles_tested and
// tiles_culled ((triangle, tile) pairs tested), and for Hierarchical tiles_lit, tiles_shadowed
// and tiles_boundary. Background pixels keep stencil 0, as in the per-pixel passes.
Image<int32_t> tiledVolumeStencil(const ShadowVolumeSet& volumes, const DepthBuffer& depth,
                                  const TiledVolumeStencilOptions& options, Stats& stats);

// The same stencil, resolved into `visibility` as resolveVisibility (facing_away.h) resolves it
// (1 on the background, 0 where the visible triangle faces away from the light or the stencil
// is non-zero, else 1) inside the pass, a row of bin tiles at a time along the image's rows:
// each tile that wrote keeps a stencil of its own, the others read as 0, and no frame-sized
// stencil is cleared. The same counters.
void tiledVolumeVisibility(const ShadowVolumeSet& volumes, const EyeBuffers& eye,
                           const FacingAway& away, const TiledVolumeStencilOptions& options,
                           Image<float>& visibility, Stats& stats);

}  // namespace penumbra
