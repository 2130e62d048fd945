#pragma once
// Options of the hard shadow volumes (`volume`), and how shadow volumes count, which the
// penumbra wedges share (wedge_options.h). For typed access to a technique's options:
//   config.options<penumbra::VolumeOptions>().mode = penumbra::VolumeMode::ZFail;
#include <string>

namespace penumbra {

// How shadow volumes count: from the eye (z-pass, Heidmann) or from infinity (z-fail,
// Everitt & Kilgard). Auto picks z-fail per caster only where the eye may be inside its volume.
enum class VolumeMode { Auto, ZPass, ZFail };
std::string volumeModeName(VolumeMode mode);  // "auto", "zpass", "zfail"

struct VolumeOptions {
  VolumeMode mode = VolumeMode::Auto;
  // Polygons that cover a whole culling tile and pass its depth test everywhere add to one
  // coarse value per tile, not to each pixel: the z-min trivial accept of Aila's 2005 thesis
  // (section 1.5) feeding a two-level stencil (raster/tile_offsets.h). The stencil ends the same
  // bit for bit; false gives the papers' per-pixel passes.
  bool two_level_stencil = true;
};

}  // namespace penumbra
