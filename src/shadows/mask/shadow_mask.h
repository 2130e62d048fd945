#pragma once
// Roettger, Irion and Ertl's shadow mask (2002, sections 4.2 to 4.4) for one point light: the
// hard shadow volumes drawn into an 8-bit buffer with double and halve blends, one volume at a
// time (mask_volumes.h), then normalised by full-window rectangles into a bilevel mask.
#include <cstdint>
#include <string>
#include <vector>

#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"
#include "shadows/mask/mask_counters.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/mask/mask_kernel.h"
#include "shadows/mask/mask_values.h"

namespace penumbra {

// The mask buffer, row-major, maskBytesPerPixel(layout) bytes per pixel (mask_kernel.h).
class MaskBuffer {
 public:
  MaskBuffer(int width, int height, MaskLayout layout, uint32_t fill);
  int width() const { return width_; }
  int height() const { return height_; }
  MaskLayout layout() const { return layout_; }
  int bytesPerPixel() const { return maskBytesPerPixel(layout_); }
  // The pixel's 8-bit mask value (alpha, or R which equals G and B).
  uint32_t value(int x, int y) const {
    return bytes_[(size_t(y) * size_t(width_) + size_t(x)) * size_t(bytesPerPixel())];
  }
  uint8_t* pixel(int x, int y) {
    return bytes_.data() + (size_t(y) * size_t(width_) + size_t(x)) * size_t(bytesPerPixel());
  }
  // Writes `v` to the pixel's mask channel(s), as mask_kernel.h lays them out.
  void set(int x, int y, uint32_t v);

 private:
  int width_, height_;
  MaskLayout layout_;
  std::vector<uint8_t> bytes_;
};

struct ShadowMaskOptions {
  VolumeMode mode = VolumeMode::Auto;
  MaskNormalisation normalisation = MaskNormalisation::ThreePass;
  MaskShadowMode shadow = MaskShadowMode::Black;
  MaskLayout layout = MaskLayout::Alpha8;
  bool simd = true;
  bool normalise = true;  // false: the raw mask after the volumes (tests of section 4.2's states)
  // Not null: the casters it culls (caster_culling.h) draw no volume.
  const CasterCulling* caster_culling = nullptr;
};

// Where the 8 bits were not enough: the pixels a halving took below 1/255 (their value, and so
// possibly their lit/shadowed state, is not the stencil's) and the casters whose volumes did it.
// A caster is split into connected parts, one volume each (mask_volumes.h): `parts` says
// which of them saturated, numbered 0..part_count-1 in the order maskVolumes builds them.
struct SaturatedCaster {
  uint32_t mesh = 0;            // scene mesh index
  std::vector<uint32_t> parts;  // ascending
  uint32_t part_count = 0;      // the caster's parts that cast a volume in this frame
};
struct MaskSaturation {
  uint64_t pixels = 0;
  std::vector<SaturatedCaster> casters;  // by scene mesh index, ascending
};

// The stderr warning for one saturated caster, naming the scene, the caster (index and mesh
// name) and its saturated parts (the first 12, then how many more), and the frame's count of
// saturated pixels.
std::string saturationWarning(const std::string& technique, const Scene& scene,
                              const SaturatedCaster& caster, uint64_t pixels);

// Adds the passes "silhouette", "mask volumes" and one per normalisation rectangle, and the
// counters silhouette_edges, triangles, pixels_rasterized, z_reads, stencil_writes (mask
// writes), tiles_tested, tiles_culled and mask_saturated_pixels; fills `saturation` if given.
MaskBuffer shadowMask(const Scene& scene, const vec3& centre, const View& view,
                      const EyeBuffers& eye, const ShadowMaskOptions& options, Stats& stats,
                      MaskSaturation* saturation = nullptr);

}  // namespace penumbra
