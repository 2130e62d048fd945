#pragma once
// Options of the alias-free shadow map (`alias-free`: Aila & Laine 2004, thesis section 4.1).
// For typed access:
//   config.options<penumbra::AliasFreeOptions>().tile_samples = 32;
namespace penumbra {

struct AliasFreeOptions {
  // The light-space grid of the irregular z-buffer is sized so that its tiles hold this many
  // eye samples on average (the samples are irregular: some tiles hold more, many none). Small
  // tiles test fewer samples per covering triangle, large ones bin each triangle to fewer tiles.
  // It changes the work, never the image.
  int tile_samples = 16;
};

}  // namespace penumbra
