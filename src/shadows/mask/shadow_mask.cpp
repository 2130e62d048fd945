#include "shadows/mask/shadow_mask.h"

#include <algorithm>
#include <cstring>
#include <string>

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
// with the SIMD kernel's padding after it.
struct MaskTile {
  alignas(64) uint8_t bytes[kBinTileSize * kBinTileSize * 4 + kMaskKernelPadding];
};

struct MaskTileWork {
  KernelCounts kernel;
  CullTally tally;
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

}  // namespace

MaskBuffer shadowMask(const Scene& scene, const vec3& centre, const View& view,
                      const EyeBuffers& eye, const ShadowMaskOptions& options, Stats& stats) {
  const DepthBuffer& depth = eye.depth;
  const int width = depth.width(), height = depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "the eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  const MaskVolumes volumes = maskVolumes(scene, centre, view, eye, options.mode, stats);
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
      MaskTileWork& w = work[tile];
      TileCopy<float> tile_depth(depth.depth, box);
      MaskTile tile_mask;
      for (int y = box.y0; y <= box.y1; ++y)
        std::memcpy(tile_mask.bytes + size_t(y - box.y0) * kBinTileSize * bytes,
                    mask.pixel(box.x0, y), size_t(box.x1 - box.x0 + 1) * bytes);
      const MaskTarget target{tile_depth.data(), tile_mask.bytes, kBinTileSize, box.x0, box.y0,
                              options.layout};
      // One volume at a time: first its polygons that add to the stencil (front faces with
      // z-pass, back faces with z-fail), then those that subtract (section 4.2: "the front
      // faces are drawn first").
      const auto draw = [&](const SetupTriangle& t, bool positive) {
        const bool zfail = (t.flags & kZFail) != 0;
        const int32_t contribution = t.payload * t.facing * (zfail ? -1 : 1);
        if (contribution == 0 || (contribution > 0) != positive) return;
        TileEdges e;
        if (!setupTileRect(t, box.x0, box.y0, box.x1, box.y1, e)) return;
        const MaskBlend blend{positive == positive_doubles,
                              std::min(contribution > 0 ? contribution : -contribution,
                                       int32_t(kMaskMaxSteps))};
        const DepthRule rule = zfail ? DepthRule::NotCloser : DepthRule::Closer;
        forEachCullRect(
            t, e, depth, kBinTileLevel,
            [&](const TileEdges& sub, float zmin, float zmax) {
              return depthRuleTiles(t, sub, zfail, zmin, zmax, false) == DepthRuleTiles::None
                         ? 0
                         : 1;
            },
            [&](const TileEdges& rect, int) {
              maskKernel(rect, blend, rule, target, w.kernel, options.simd);
            },
            w.tally);
      };
      for (const uint32_t* run = first; run != last;) {
        const uint32_t volume = volumes.volume_of[*run];
        const uint32_t* end = run;
        while (end != last && volumes.volume_of[*end] == volume) ++end;
        for (const bool positive : {true, false})
          for (const uint32_t* k = run; k != end; ++k) draw(volumes.setup[*k], positive);
        run = end;
      }
      for (int y = box.y0; y <= box.y1; ++y)
        std::memcpy(mask.pixel(box.x0, y), tile_mask.bytes + size_t(y - box.y0) * kBinTileSize * bytes,
                    size_t(box.x1 - box.x0 + 1) * bytes);
    });
    for (const MaskTileWork& w : work) {
      stats.pixels_rasterized += w.kernel.covered;
      stats.z_reads += w.kernel.covered;
      stats.stencil_writes += w.kernel.writes;
      stats.tiles_tested += w.tally.tested;
      stats.tiles_culled += w.tally.culled;
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
    rectanglePass(mask, stats,
                  mode == MaskShadowMode::Attenuated ? "mask rectangle 3 +1/2" : "mask rectangle 3 *2",
                  [mode](uint32_t v) { return threePassRectangle3(v, mode); });
  }
  return mask;
}

}  // namespace penumbra
