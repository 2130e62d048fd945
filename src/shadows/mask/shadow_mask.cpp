#include "shadows/mask/shadow_mask.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/binning.h"
#include "raster/cull_tiles.h"
#include "raster/tile_copy.h"
#include "shadows/mask/mask_volumes.h"

namespace penumbra {

MaskBuffer::MaskBuffer(int width, int height, MaskLayout layout, uint32_t fill)
    : width_(width), height_(height), layout_(layout) {
  bytes_.resize(size_t(width) * size_t(height) * size_t(bytesPerPixel()));
  if (layout == MaskLayout::Alpha8) {
    std::fill(bytes_.begin(), bytes_.end(), uint8_t(fill));
  } else {
    for (size_t i = 0; i < bytes_.size(); i += 4) {
      bytes_[i] = bytes_[i + 1] = bytes_[i + 2] = uint8_t(fill);
      bytes_[i + 3] = 0;
    }
  }
}

void MaskBuffer::set(int x, int y, uint32_t v) {
  uint8_t* p = pixel(x, y);
  p[0] = uint8_t(v);
  if (layout_ == MaskLayout::Rgba8) p[1] = p[2] = uint8_t(v);
}

namespace {

// A bin tile of the mask in a contiguous copy of its own, as the stencil's (raster/tile_copy.h),
// with the SIMD kernel's padding after it, and the tile's saturation flags (mask_kernel.h).
struct MaskTile {
  alignas(64) uint8_t bytes[kBinTileSize * kBinTileSize * 4 + kMaskKernelPadding];
  uint8_t saturated[kBinTileSize * kBinTileSize] = {};
};

struct MaskTileWork {
  KernelCounts kernel;
  CullTally tally;
  uint64_t saturated_pixels = 0;
  std::vector<uint32_t> saturated_volumes;  // in drawing order, each once
};

// One full-window rectangle: fn on every pixel's value, rows in parallel.
template <class Fn>
void rectanglePass(MaskBuffer& mask, Stats& stats, const std::string& name, Fn&& fn) {
  PassTimer timer(stats, name);
  parallelFor(size_t(mask.height()), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < mask.width(); ++x) mask.set(x, y, fn(mask.value(x, y)));
  });
}

// Draws one volume polygon into a tile if it halves (or doubles, as `halves` says) the mask
// there; returns the pixels whose halving lost a power of two.
uint64_t drawPolygon(const SetupTriangle& t, bool halves, bool positive_doubles,
                     const TileBox& box, const DepthBuffer& depth, const MaskTarget& target,
                     bool simd, MaskTileWork& w) {
  const bool zfail = (t.flags & kZFail) != 0;
  const int32_t contribution = t.payload * t.facing * (zfail ? -1 : 1);
  if (contribution == 0 || ((contribution > 0) == positive_doubles) == halves) return 0;
  TileEdges e;
  if (!setupTileRect(t, box.x0, box.y0, box.x1, box.y1, e)) return 0;
  const MaskBlend blend{!halves, std::min(contribution > 0 ? contribution : -contribution,
                                          int32_t(kMaskMaxSteps))};
  const DepthRule rule = zfail ? DepthRule::NotCloser : DepthRule::Closer;
  uint64_t lost = 0;
  forEachCullRect(
      t, e, depth, kBinTileLevel,
      [&](const TileEdges& sub, float zmin, float zmax) {
        return depthRuleTiles(t, sub, zfail, zmin, zmax, false) == DepthRuleTiles::None ? 0 : 1;
      },
      [&](const TileEdges& rect, int) {
        lost += maskKernel(rect, blend, rule, target, w.kernel, simd);
      },
      w.tally);
  return lost;
}

// The volumes overlapping one bin tile, one after the other. Section 4.2 draws each volume's
// front faces first (with z-pass, the stencil-increasing ones), which is exact only while at
// most two of them cover a pixel before a decreasing one: the doubling clamps at 1 and the later
// halvings take the pixel to "lit". Penumbra draws each volume's halving polygons first, then
// its doubling ones: with the three-pass normalisation a pixel starts at 1/4 and a closed
// volume's count is >= 0, so the halvings have six powers of two below it (down to 1/255) and
// the doublings can only clamp once the count is reached; with max-blend (start 1, the
// increasing polygons halve) the same order has eight. Halvings past that are flagged per pixel.
void drawTileVolumes(const MaskVolumes& volumes, const uint32_t* first, const uint32_t* last,
                     const TileBox& box, const DepthBuffer& depth, const MaskTarget& target,
                     bool positive_doubles, bool simd, MaskTileWork& w) {
  for (const uint32_t* run = first; run != last;) {
    const uint32_t volume = volumes.volume_of[*run];
    const uint32_t* end = run;
    while (end != last && volumes.volume_of[*end] == volume) ++end;
    uint64_t lost = 0;
    for (const bool halves : {true, false})
      for (const uint32_t* k = run; k != end; ++k)
        lost +=
            drawPolygon(volumes.setup[*k], halves, positive_doubles, box, depth, target, simd, w);
    if (lost != 0) w.saturated_volumes.push_back(volume);
    run = end;
  }
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x)
      w.saturated_pixels += target.saturated[(y - box.y0) * target.stride + (x - box.x0)];
}

// The casters, in scene order, whose volumes lost a halving in some tile, each with its
// saturated parts (a part's number: how many volumes of the same caster come before it).
std::vector<SaturatedCaster> saturatedCasters(const MaskVolumes& volumes,
                                              const std::vector<MaskTileWork>& work) {
  std::vector<bool> lost(volumes.caster_of.size(), false);
  for (const MaskTileWork& w : work)
    for (const uint32_t v : w.saturated_volumes) lost[v] = true;
  std::vector<SaturatedCaster> out;
  std::vector<uint32_t> parts_so_far;
  for (uint32_t v = 0; v < volumes.caster_of.size(); ++v) {
    const uint32_t c = volumes.caster_of[v];
    if (c >= parts_so_far.size()) parts_so_far.resize(c + 1, 0);
    const uint32_t part = parts_so_far[c]++;
    if (!lost[v]) continue;
    auto it = std::find_if(out.begin(), out.end(),
                           [c](const SaturatedCaster& s) { return s.mesh == c; });
    if (it == out.end()) it = out.insert(out.end(), SaturatedCaster{c, {}, 0});
    it->parts.push_back(part);
  }
  for (SaturatedCaster& s : out) s.part_count = parts_so_far[s.mesh];
  std::sort(out.begin(), out.end(),
            [](const SaturatedCaster& a, const SaturatedCaster& b) { return a.mesh < b.mesh; });
  return out;
}

}  // namespace

MaskBuffer shadowMask(const Scene& scene, const vec3& centre, const View& view,
                      const EyeBuffers& eye, const ShadowMaskOptions& options, Stats& stats,
                      MaskSaturation* saturation) {
  const DepthBuffer& depth = eye.depth;
  const int width = depth.width(), height = depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "the eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  const MaskVolumes volumes =
      maskVolumes(scene, centre, view, eye, options.mode, stats, options.caster_culling);
  const uint32_t initial = maskInitialValue(options.normalisation);
  MaskBuffer mask(width, height, options.layout, initial);
  {
    PassTimer timer(stats, "mask volumes");
    const TileBins bins = binTriangles(volumes.setup, width, height);
    std::vector<MaskTileWork> work(bins.tileCount());
    const int bytes = mask.bytesPerPixel();
    const bool positive_doubles = maskPositiveDoubles(options.normalisation);
    parallelFor(bins.tileCount(), [&](size_t tile) {
      const uint32_t* first = bins.triangles.data() + bins.offsets[tile];
      const uint32_t* last = bins.triangles.data() + bins.offsets[tile + 1];
      if (first == last) return;  // the buffer holds the initial value already
      const int tx = int(tile % size_t(bins.tiles_x)), ty = int(tile / size_t(bins.tiles_x));
      const TileBox box{tx * kBinTileSize, ty * kBinTileSize,
                        std::min(width, (tx + 1) * kBinTileSize) - 1,
                        std::min(height, (ty + 1) * kBinTileSize) - 1};
      TileCopy<float> tile_depth(depth.depth, box);
      auto tile_mask = std::make_unique<MaskTile>();
      for (int y = box.y0; y <= box.y1; ++y)
        std::memcpy(tile_mask->bytes + size_t(y - box.y0) * kBinTileSize * bytes,
                    mask.pixel(box.x0, y), size_t(box.x1 - box.x0 + 1) * bytes);
      MaskTarget target{tile_depth.data(), tile_mask->bytes, kBinTileSize, box.x0, box.y0,
                        options.layout};
      target.saturated = tile_mask->saturated;
      drawTileVolumes(volumes, first, last, box, depth, target, positive_doubles, options.simd,
                      work[tile]);
      for (int y = box.y0; y <= box.y1; ++y)
        std::memcpy(mask.pixel(box.x0, y),
                    tile_mask->bytes + size_t(y - box.y0) * kBinTileSize * bytes,
                    size_t(box.x1 - box.x0 + 1) * bytes);
    });
    uint64_t saturated_pixels = 0;
    for (const MaskTileWork& w : work) {
      stats.pixels_rasterized += w.kernel.covered;
      stats.z_reads += w.kernel.covered;
      stats.stencil_writes += w.kernel.writes;
      stats.tiles_tested += w.tally.tested;
      stats.tiles_culled += w.tally.culled;
      saturated_pixels += w.saturated_pixels;
    }
    stats.count(kMaskSaturatedPixels, saturated_pixels);
    if (saturation) {
      saturation->pixels = saturated_pixels;
      saturation->casters = saturatedCasters(volumes, work);
    }
  }
  if (!options.normalise) return mask;
  // Section 4.3, Figure 4, and section 4.4, Figure 5: each rectangle a pass over the window.
  if (options.normalisation == MaskNormalisation::MaxBlend) {
    rectanglePass(mask, stats, "mask rectangle 1 max 1/2", maxBlendRectangle);
  } else {
    rectanglePass(mask, stats, "mask rectangle 1 *2", threePassRectangle1);
    rectanglePass(mask, stats, "mask rectangle 2 invert", threePassRectangle2);
    const MaskShadowMode mode = options.shadow;
    rectanglePass(
        mask, stats,
        mode == MaskShadowMode::Attenuated ? "mask rectangle 3 +1/2" : "mask rectangle 3 *2",
        [mode](uint32_t v) { return threePassRectangle3(v, mode); });
  }
  return mask;
}

std::string saturationWarning(const std::string& technique, const Scene& scene,
                              const SaturatedCaster& caster, uint64_t pixels) {
  // A scan may saturate dozens of parts: the first kListedParts name them, a count the rest.
  constexpr size_t kListedParts = 12;
  std::string parts;
  for (size_t i = 0; i < caster.parts.size() && i < kListedParts; ++i)
    parts += (i == 0 ? "" : ", ") + std::to_string(caster.parts[i]);
  if (caster.parts.size() > kListedParts)
    parts += fmt::format(" and {} more", caster.parts.size() - kListedParts);
  return fmt::format(
      "warning: {}: scene \"{}\": the shadow volume of caster {} (\"{}\"), connected part{} {} "
      "of its {}, needs more halvings than the 8-bit mask holds; {} pixel{} of this frame may "
      "differ from the stencil (counter mask_saturated_pixels)\n",
      technique, scene.name, caster.mesh, scene.meshes[caster.mesh].name,
      caster.parts.size() == 1 ? "" : "s", parts, caster.part_count, pixels,
      pixels == 1 ? "" : "s");
}

}  // namespace penumbra
