#pragma once
// The one technique contract (DESIGN.md): given the eye pass's buffers, a light, the scene and
// the view, a technique writes the light visibility of every pixel's visible point, in [0, 1],
// and its work counters. Techniques read the eye buffers and never write them.
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"

namespace penumbra {

enum class TechniqueKind {
  Reference,      // ray-traced oracle (Embree): hard = one ray to the centre, soft = N rays
  ShadowVolume,   // hard shadow volumes, z-pass / z-fail, integer stencil
  Wedge2002,      // penumbra wedges as in the 2002 paper: entry/exit points per fragment
  WedgeThreePass, // 2004 restructured algorithm, three-pass implementation (section 6.1)
  WedgeSinglePass,// 2004 restructured algorithm, single-pass implementation (section 6.2)
};

// Tile z-min/z-max occlusion culling of the wedge passes (2004 paper, section 4).
enum class CullMode {
  None,  // every covered pixel reads its depth
  ZMax,  // only the test that common hardware has: skip tiles whose farthest depth is nearer
         // than the primitive (for the penumbra: than the whole wedge)
  Full,  // z-min and z-max: also skip tiles entirely in front of the wedge, and tiles whose
         // screen-space box lies outside a wedge plane (n- and p-vertex tests, Figure 7)
};

// How shadow volumes count: from the eye (z-pass, Heidmann) or from infinity (z-fail,
// Everitt & Kilgard). Auto picks z-fail per caster only where the eye may be inside its volume.
enum class VolumeMode { Auto, ZPass, ZFail };

struct TechniqueOptions {
  TechniqueKind kind = TechniqueKind::ShadowVolume;
  VolumeMode volume_mode = VolumeMode::Auto;
  // Oracle: rays per pixel over the spherical light (1..4096); with a point light (radius 0),
  // or when `hard` is set, one ray to the light centre.
  int rays = 256;
  bool hard = false;
  uint64_t seed = 1;
  bool simd = true;           // false: run every hot loop's scalar twin
  // Penumbra wedges.
  CullMode cull = CullMode::Full;
  // Culling tiles of 2^tile_level pixels, 1..8. 16 x 16 by default: the fastest frame of
  // `penumbra bench` on fractal and year2002 and within 5 % of it on columns (32 x 32 there), for
  // both implementations (the paper's optimum is 8 x 8 to 32 x 32, section 7;
  // docs/reproducing-2004.md).
  int tile_level = 4;
  // Culling tiles of the three-pass implementation's umbra pass, a stencil shadow volume pass
  // (section 6.1; the paper drew it on the GPU, culled by the hardware's own tiles): 2^5 =
  // 32 x 32, the bin tiles. Its polygons are few, long and mostly inside their tiles, and
  // smaller tiles cost more in tile tests and kernel calls than they save in pixels (columns
  // three-pass umbra pass, 16 x 16: 640x427 1.98 ms, 1920x1080 7.3 ms; 32 x 32: 1.73 / 6.1 ms,
  // medians of 3). 0: the same tiles as the penumbra pass (tile_level), as `bench` sweeps them.
  int umbra_tile_level = 5;
  // Umbra polygons (hard shadow volumes; the wedges' front planes with full culling) that cover
  // a whole culling tile and pass its depth test everywhere add to one coarse value per tile,
  // not to each pixel: the two-level stencil of Aila's 2005 thesis (section 4.3). The buffers
  // end the same bit for bit; false gives the 2004 paper's passes (its evaluation, `bench`).
  bool two_level_stencil = true;
  bool smooth_falloff = false;  // s' = 3 s^2 - 2 s^3 (2002 paper, section 4.2)
  bool acute_wedges = false;    // extra wedges around acute silhouette vertices (Figure 7)
  int light_count = 1;          // LI units per light are 255 / light_count (2002 paper, section 7)
  bool show_progress = false; // progress bar on a terminal for long work
};

struct TechniqueResult {
  Image<float> visibility;  // per pixel, in [0, 1]; 1 on background pixels
  Stats stats;
};

TechniqueResult renderShadows(const TechniqueOptions& options, const Scene& scene,
                              const Light& light, const View& view, const EyeBuffers& eye);

// Name <-> kind, for the CLI and stats files ("reference", "volume", "wedge-2002",
// "wedge-3pass", "wedge-1pass").
std::string techniqueName(TechniqueKind kind);
TechniqueKind parseTechniqueName(const std::string& name);  // throws penumbra::Error
std::vector<std::string> techniqueNames();
std::string cullModeName(CullMode mode);
CullMode parseCullMode(const std::string& name);  // "none", "zmax", "full"; throws

}  // namespace penumbra
