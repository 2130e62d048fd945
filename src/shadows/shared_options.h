#pragma once
// The options several techniques take, declared once, so that `--volume-mode`, `--tile-size`,
// `--samples` and `--seed` mean the same on every technique that has them and read the same in
// `penumbra techniques NAME`. Each adds its spec to a technique's table and returns the table.
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "core/error.h"
#include "shadows/technique_options.h"
#include "shadows/volume_options.h"

namespace penumbra {

// How shadow volumes count: from the eye (z-pass), from infinity (z-fail), or per caster.
template <class Options>
OptionTableBuilder<Options>& volumeModeOption(OptionTableBuilder<Options>& table,
                                              VolumeMode Options::*field) {
  return table.choice("volume-mode", "count from the eye (zpass), from infinity (zfail), or auto",
                      field,
                      {{"auto", VolumeMode::Auto}, {"zpass", VolumeMode::ZPass},
                       {"zfail", VolumeMode::ZFail}});
}

// The level of a tile `size` pixels wide (size = 2^level) in [min_level, max_level]; throws
// naming the option `what` otherwise.
inline int tileLevelOfSize(int64_t size, int min_level, int max_level, const std::string& what) {
  for (int level = min_level; level <= max_level; ++level)
    if (size == int64_t(1) << level) return level;
  throw Error(fmt::format("{} {} is not a power of two in {}..{}", what, size, 1 << min_level,
                          1 << max_level));
}

// `--tile-size`: a power of two in 2^min_level..2^max_level pixels, kept as its level. `what`
// names the tiles ("culling", "edge binning").
template <class Options>
OptionTableBuilder<Options>& tileSizeOption(OptionTableBuilder<Options>& table,
                                            const std::string& what, int Options::*level,
                                            int min_level, int max_level) {
  return table.integer(
      "tile-size",
      fmt::format("{} tile size in pixels, a power of two in {}..{}", what, 1 << min_level,
                  1 << max_level),
      int64_t(1) << min_level, int64_t(1) << max_level,
      [level, min_level, max_level](Options& o, int64_t size) {
        o.*level = tileLevelOfSize(size, min_level, max_level, "--tile-size");
      },
      [level](const Options& o) { return int64_t(1) << (o.*level); });
}

// `--samples`: points on the light, min_samples..max_samples. Interactive previews take
// kPreviewSamples (OptionSpec::preview) where the value set is larger: noisier, and faster in
// proportion (exact's default 256 samples: a sixteenth of the per-pixel work).
inline constexpr int64_t kPreviewSamples = 16;
template <class Options, class Int>
OptionTableBuilder<Options>& samplesOption(OptionTableBuilder<Options>& table,
                                           const std::string& help, Int Options::*field,
                                           int64_t min_samples, int64_t max_samples) {
  table.integer("samples", help, field, min_samples, max_samples);
  if (kPreviewSamples >= min_samples && kPreviewSamples <= max_samples)
    table.preview(std::to_string(kPreviewSamples));
  return table;
}

// `--seed`: the random seed of a technique's light samples; `what` says what it seeds.
template <class Options, class Int>
OptionTableBuilder<Options>& seedOption(OptionTableBuilder<Options>& table,
                                        const std::string& what, Int Options::*field) {
  return table.integer("seed", "random seed of " + what, field, 0, INT64_MAX);
}

}  // namespace penumbra
