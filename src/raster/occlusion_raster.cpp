#include "raster/occlusion_raster.h"

#include <algorithm>
#include <vector>

#include "core/parallel.h"
#include "raster/binning.h"
#include "raster/fixed_point.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"

namespace penumbra {

void clearOcclusionBuffer(DepthBuffer& occlusion, int width, int height) {
  occlusion.depth.resize(width, height, 0.0f);
  occlusion.allocateTileRanges();
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    occlusion.tiles[level].zmin.fill(0.0f);
    occlusion.tiles[level].zmax.fill(0.0f);
  }
}

uint64_t drawOccluders(const ClipTriangles& triangles, DepthBuffer& occlusion, bool simd) {
  const int width = occlusion.width(), height = occlusion.height();
  const std::vector<SetupTriangle> setup = setupTriangles(triangles, width, height);
  const TileBins bins = binTriangles(setup, width, height);
  parallelFor(bins.tileCount(), [&](size_t tile) {
    if (bins.offsets[tile] == bins.offsets[tile + 1]) return;
    const int tx = int(tile % size_t(bins.tiles_x)), ty = int(tile / size_t(bins.tiles_x));
    const TileBox box{tx * kBinTileSize, ty * kBinTileSize,
                      std::min(width, (tx + 1) * kBinTileSize) - 1,
                      std::min(height, (ty + 1) * kBinTileSize) - 1};
    // As the eye pass (raster/rasterizer.cpp): the tile in a copy that stays in L1; here it
    // starts from what earlier batches drew. The ids are written and never read.
    TileCopy<float> tile_depth(occlusion.depth, box);
    TileCopy<uint32_t> tile_primitive;
    DepthTarget target{tile_depth.data(), tile_primitive.data(), kBinTileSize};
    target.x0 = box.x0;
    target.y0 = box.y0;
    KernelCounts counts;
    const uint32_t end = bins.offsets[tile + 1];
    for (uint32_t k = bins.offsets[tile]; k < end; ++k) {
      if (k + kBinLookahead < end)
        prefetchSetupTriangle(setup[bins.triangles[k + kBinLookahead]]);
      const SetupTriangle& t = setup[bins.triangles[k]];
      TileEdges e;
      if (setupTileEdges(t, box.x0, box.y0, box.x1, box.y1, e))
        depthKernel(e, uint32_t(t.payload), target, counts, simd);
    }
    occlusion.setBinTileRanges(tile_depth.data(), kBinTileSize, box.x0, box.y0, box.x1, box.y1);
    tile_depth.storeTo(occlusion.depth, box);
  });
  occlusion.finishTileRanges();
  return setup.size();
}

}  // namespace penumbra
