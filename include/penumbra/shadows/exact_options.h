#pragma once
// Options of the exact soft shadow volumes (`exact`). For typed access to a technique's options:
//   config.options<penumbra::ExactOptions>().samples = 1024;
#include <cstdint>

namespace penumbra {

struct ExactOptions {
  // Light samples per pixel (1..4096): one stratified set shared by every pixel, the set the
  // oracle traces with `--sample-set fixed` and the same seed (reference_options.h).
  int samples = 256;
  uint64_t seed = 1;
  // Edges are binned to square tiles of 2^tile_level pixels and culled against each tile's
  // z-min/z-max (2004 paper, section 4); 3 is 8x8.
  int tile_level = 3;
};

}  // namespace penumbra
