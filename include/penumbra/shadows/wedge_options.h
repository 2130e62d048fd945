#pragma once
// Options of the penumbra wedges (`wedge-2002`, `wedge-3pass`, `wedge-1pass`). For typed access
// to a technique's options:
//   config.options<penumbra::WedgeOptions>().cull = penumbra::CullMode::ZMax;
#include <string>

#include <penumbra/shadows/volume_options.h>

namespace penumbra {

enum class WedgeAlgorithm {
  Original2002,  // entry/exit points per fragment, z-pass, no culling (2002 paper, section 6)
  ThreePass,     // 2004 restructured algorithm, three-pass implementation (section 6.1)
  SinglePass,    // 2004 restructured algorithm, single-pass implementation (section 6.2)
};
std::string wedgeTechniqueName(WedgeAlgorithm algorithm);  // "wedge-2002", "wedge-3pass", ...

// Tile z-min/z-max occlusion culling of the wedge passes (2004 paper, section 4).
enum class CullMode {
  None,  // every covered pixel reads its depth
  ZMax,  // only the test that common hardware has: skip tiles whose farthest depth is nearer
         // than the primitive (for the penumbra: than the whole wedge)
  Full,  // z-min and z-max: also skip tiles entirely in front of the wedge, and tiles whose
         // screen-space box lies outside a wedge plane (n- and p-vertex tests, Figure 7)
};
std::string cullModeName(CullMode mode);  // "none", "zmax", "full"
CullMode parseCullMode(const std::string& name);  // throws penumbra::Error naming the known

struct WedgeOptions {
  // Counted from the eye or from infinity per caster (2004 paper, section 5). The 2002
  // algorithm predates z-fail for wedges (its section 8) and always counts from the eye.
  VolumeMode volume_mode = VolumeMode::Auto;
  CullMode cull = CullMode::Full;
  // Culling tiles of 2^tile_level pixels, 1..8. 16 x 16 by default: the fastest frame of
  // `penumbra bench` on fractal and year2002 and close to it on columns, for both
  // implementations (the paper's optimum is 8 x 8 to 32 x 32, section 7; the times are in
  // docs/reproducing-2004.md).
  int tile_level = 4;
  // Culling tiles of the three-pass implementation's umbra pass, a stencil shadow volume pass
  // (section 6.1; the paper drew it on the GPU, culled by the hardware's own tiles): 2^5 =
  // 32 x 32, the bin tiles. Its polygons are few, long and mostly inside their tiles, and
  // smaller tiles cost more in tile tests and kernel calls than they save in pixels
  // (bench/README.md). 0: the same tiles as the penumbra pass (tile_level), as `bench` sweeps.
  int umbra_tile_level = 5;
  // Umbra polygons (the wedges' front planes, with full culling) that cover a whole culling
  // tile and pass its depth test everywhere add to one coarse value per tile, not to each
  // pixel (the z-min trivial accept of Aila's 2005 thesis, section 1.5, feeding a two-level
  // stencil: raster/tile_offsets.h). The LI buffer ends the same bit for bit; false gives the
  // 2004 paper's passes (its evaluation, `bench`).
  bool two_level_stencil = true;
  bool smooth_falloff = false;  // s' = 3 s^2 - 2 s^3 (2002 paper, section 4.2)
  // Open meshes cast one facing (silhouette.h, SolidWithHoles); rays through their holes miss
  // it, and a second pass with the other facing keeps those points dark (wedge_technique.cpp).
  // It runs only when some open mesh has triangles facing the light both ways (a terrain, a
  // scan with an open base), and costs about one more wedge pass over those meshes. false: the
  // papers' one facing, faster, with light through the holes.
  bool other_facing_pass = true;
};

}  // namespace penumbra
