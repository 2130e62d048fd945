// The alias-free shadow map (Aila & Laine, "Alias-Free Shadow Maps", EGSR 2004: publication P5
// of Aila's 2005 thesis, section 4.1), in our terms (docs/alias-free-shadow-maps.md):
//
// 1. Samples. Every covered pixel's shaded point is the oracle's: RayOrigins::start puts the
//    depth-buffer point back on its visible triangle and lifts it off toward the eye, and the
//    float ray origin the oracle traces from is the sample (ray_origin.h). As in the oracle, a
//    point whose own surface faces away from the light centre is in shadow without a test
//    (RayStart::intoSurface), and a point at the light centre is lit.
// 2. The irregular z-buffer. Samples, relative to the light centre, are projected onto the
//    light's image plane (one frustum, or six cube faces: light_grids.h) and binned into
//    light-space tiles, stored tile by tile in blocks of kOccluderBlock for the SIMD kernel.
// 3. Binning the occluders. Every scene triangle is clipped to each grid's frustum; the tiles
//    its projected bounds cover are its candidates (a conservative rasterization over the
//    tiles). A (triangle, tile) pair is culled when the triangle's nearest point to the
//    light is farther than every sample of the tile: it cannot lie between the light and any
//    of them (the light-space analogue of z-max culling).
// 4. Tests. Per tile, every triangle binned to it is tested against the tile's samples, exactly
//    and in 3D (occluder_test.h): the sample is in shadow when the segment from the light centre
//    to it crosses the triangle. Tiles are independent work items (no two share a sample), and
//    the result of a sample is the OR over triangles, so output and counters are the same for
//    any thread count; the kernel is SIMD with a scalar twin.
//
// There is no bias: the visible triangle cannot shadow its own sample from the light's side,
// because the sample is lifted off it toward the eye (a light on the other side is decided by
// intoSurface), and neighbours across its edges are tested like any triangle against the same
// point the oracle traces from.
//
// Counters: z_reads, one depth read per covered pixel (as the oracle); light_samples, the
// samples in the irregular z-buffer; triangles, occluders set up and binned to some grid;
// tiles_tested and tiles_culled, (triangle, light-space tile) pairs for tiles holding samples
// and those culled by distance; sample_tests, (triangle, sample) pairs tested.
#include "shadows/aliasfree/alias_free_technique.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "shadows/aliasfree/alias_free_counters.h"
#include "shadows/aliasfree/light_grids.h"
#include "shadows/aliasfree/occluder_test.h"
#include "shadows/stages/light_sampling/ray_origin.h"

namespace penumbra {
namespace {

constexpr uint32_t kNoSample = 0xffffffffu;
constexpr size_t kTrianglesPerChunk = 1024;
constexpr size_t kSamplesPerChunk = 65536;  // at least, per work item of the counting sort
constexpr size_t kMaxSampleChunks = 16;
constexpr size_t kTilesPerItem = 256;

// A triangle is culled from a tile when its nearest point is farther from the light than the
// tile's farthest sample by more than this relative margin (distances are rounded in double).
constexpr double kCullMargin = 1e-9;

struct alignas(kOccluderSampleAlignment) DoubleBlock {
  double v[kOccluderBlock];
};
struct alignas(kOccluderSampleAlignment) FlagBlock {
  int64_t v[kOccluderBlock];
};

struct Occluder {
  OccluderTest test;
  double nearest = 0.0;  // distance from the light centre to the triangle's nearest point
};

// Buffers of one render, kept by the prepared technique for the next: a frame's samples take
// tens of megabytes at 1920 x 1080, and fresh allocations that large come from the kernel page
// by page every frame. Sizes only grow; contents are never carried from one render to the next.
struct Scratch {
  std::vector<dvec3> row_d, d;  // samples minus the light centre: per row in place, then packed
  std::vector<uint32_t> row_x, sample_pixel, chunk_tile, slot_sample;
  std::vector<DoubleBlock> x, y, z;
};

template <class T>
T* atLeast(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
  return v.data();
}

struct BinnedTriangle {
  uint32_t triangle;
  uint32_t grid;
  TileRange range;
};

class AliasFree final : public PreparedTechnique {
 public:
  AliasFree(const AliasFreeOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {
    for (uint32_t m = 0; m < scene.meshes.size(); ++m)
      for (uint32_t t = 0; t < scene.meshes[m].triangleCount(); ++t) where_.emplace_back(m, t);
    triangle_count_ = where_.size();
  }
  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  AliasFreeOptions options_;
  const Scene& scene_;
  std::vector<std::pair<uint32_t, uint32_t>> where_;  // (mesh, triangle) of every global id
  size_t triangle_count_ = 0;
  // One render at a time uses the kept buffers; a concurrent one makes its own.
  mutable std::mutex scratch_mutex_;
  mutable Scratch scratch_;
};

// The irregular z-buffer (step 2): the samples relative to the light centre, tile by tile in
// blocks of kOccluderBlock (x, y, z apart for the kernel), each tile padded to whole blocks.
struct IrregularZBuffer {
  std::optional<LightGrids> grids;
  size_t tiles = 0;
  std::vector<size_t> tile_block;  // first block of every tile, then the total
  std::vector<uint32_t> tile_samples;
  std::vector<double> tile_farthest;
  double farthest = 0.0;  // of all samples
  DoubleBlock *x_blocks = nullptr, *y_blocks = nullptr, *z_blocks = nullptr;
  uint32_t* slot_sample = nullptr;  // per slot, its sample, or kNoSample for padding
};

// The occluders (step 3) and, per light-space tile, the list of those binned to it and not
// culled, in triangle order.
struct AliasFreeOccluderLists {
  std::vector<Occluder> occluders;
  std::vector<size_t> tile_list;  // first entry of every tile's list, then the total
  std::vector<uint32_t> lists;
};

// 1. Samples (thesis section 4.1: the visible samples, the optimal sampling points of the
// light's image plane): every row's packed at the row's start in place, rows in parallel, then
// all packed in row order into scratch.d (sample minus light centre) and scratch.sample_pixel
// (y * width + x). Points in shadow without a test get visibility 0 here.
void gatherAliasFreeSamples(const RayOrigins& origins, const EyeBuffers& eye,
                            const dvec3& centre, Scratch& scratch, Image<float>& visibility_image,
                            Stats& stats) {
  const int width = eye.depth.width(), height = eye.depth.height();
  std::vector<dvec3>& d = scratch.d;
  std::vector<uint32_t>& sample_pixel = scratch.sample_pixel;
  const size_t pixels = size_t(width) * size_t(height);
  dvec3* row_d = atLeast(scratch.row_d, pixels);
  uint32_t* row_x = atLeast(scratch.row_x, pixels);
  std::vector<uint64_t> row_reads(size_t(height), 0);
  std::vector<size_t> row_first(size_t(height) + 1, 0);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    const float* depth = eye.depth.depth.row(y);
    const uint32_t* primitive = eye.primitive.row(y);
    float* visibility = visibility_image.row(y);
    const size_t base = row * size_t(width);
    size_t count = 0;
    OriginTriangle triangle;  // the row's last visible triangle (RayOrigins::start)
    for (int x = 0; x < width; ++x) {
      if (!(depth[x] > 0.0f)) continue;  // background stays lit
      ++row_reads[row];
      const RayStart start = origins.start(x, y, depth[x], primitive[x], triangle);
      if (glm::length(centre - start.origin) == 0.0) continue;  // at the light: lit
      if (start.intoSurface(centre)) {
        visibility[x] = 0.0f;
        continue;
      }
      // The oracle traces from the origin rounded to float (reference_technique.cpp).
      const dvec3 sample = dvec3(vec3(start.origin)) - centre;
      if (sample == dvec3(0.0)) continue;
      row_d[base + count] = sample;
      row_x[base + count++] = uint32_t(x);
    }
    row_first[row + 1] = count;
  });
  for (size_t row = 0; row < size_t(height); ++row) {
    stats.z_reads += row_reads[row];
    row_first[row + 1] += row_first[row];
  }
  d.resize(row_first[size_t(height)]);
  sample_pixel.resize(d.size());
  parallelFor(size_t(height), [&](size_t row) {
    const size_t base = row * size_t(width);
    for (size_t k = 0; k < row_first[row + 1] - row_first[row]; ++k) {
      d[row_first[row] + k] = row_d[base + k];
      sample_pixel[row_first[row] + k] = uint32_t(base) + row_x[base + k];
    }
  });
  stats.count(kLightSamples, d.size());
}

// The first half of step 2's counting sort: per chunk of samples and tile, the chunk's first
// slot within the tile (chunk_tile), the tiles' sample counts and first blocks; `chunks` of
// `chunk_size` samples.
void countIrregularZBufferTiles(const std::vector<dvec3>& d, size_t chunks, size_t chunk_size,
                                std::vector<uint32_t>& chunk_tile, IrregularZBuffer& z) {
  const LightGrids& grids = *z.grids;
  const size_t tiles = z.tiles;
  chunk_tile.assign(chunks * tiles, 0);
  parallelFor(chunks, [&](size_t c) {
    const size_t end = std::min(d.size(), (c + 1) * chunk_size);
    for (size_t i = c * chunk_size; i < end; ++i) ++chunk_tile[c * tiles + grids.tileOf(i)];
  });
  z.tile_samples.assign(tiles, 0);
  parallelFor((tiles + kTilesPerItem - 1) / kTilesPerItem, [&](size_t item) {
    const size_t end = std::min(tiles, (item + 1) * kTilesPerItem);
    for (size_t t = item * kTilesPerItem; t < end; ++t) {
      uint32_t total = 0;
      for (size_t c = 0; c < chunks; ++c) {
        const uint32_t n = chunk_tile[c * tiles + t];
        chunk_tile[c * tiles + t] = total;
        total += n;
      }
      z.tile_samples[t] = total;
    }
  });
  z.tile_block.assign(tiles + 1, 0);
  for (size_t t = 0; t < tiles; ++t) {
    z.tile_block[t + 1] =
        z.tile_block[t] + (z.tile_samples[t] + kOccluderBlock - 1) / kOccluderBlock;
  }
}

// 2. The irregular z-buffer (thesis section 4.1: the samples binned into the light's image
// plane): samples tile by tile, each tile padded to whole blocks. A counting sort in parallel
// chunks of samples: chunk c's samples of tile t go after those of chunks before c, so every
// tile holds its samples in sample order, whatever the threads.
void buildIrregularZBuffer(const std::vector<dvec3>& d, const AliasFreeOptions& options,
                           Scratch& scratch, IrregularZBuffer& z) {
  z.grids.emplace(d, options.tile_samples);
  const LightGrids& grids = *z.grids;
  const size_t tiles = z.tiles = grids.tileCount();
  // At most kMaxSampleChunks chunks, so the per-chunk counts take at most 16 entries a tile.
  const size_t chunk_size =
      std::max(kSamplesPerChunk, (d.size() + kMaxSampleChunks - 1) / kMaxSampleChunks);
  const size_t chunks = (d.size() + chunk_size - 1) / chunk_size;
  // Per chunk and tile: the chunk's sample count, then its first slot within the tile.
  std::vector<uint32_t>& chunk_tile = scratch.chunk_tile;
  countIrregularZBufferTiles(d, chunks, chunk_size, chunk_tile, z);
  const size_t blocks = z.tile_block[tiles];
  // Every slot is written below, by a sample or as padding.
  z.x_blocks = atLeast(scratch.x, blocks);
  z.y_blocks = atLeast(scratch.y, blocks);
  z.z_blocks = atLeast(scratch.z, blocks);
  z.slot_sample = atLeast(scratch.slot_sample, blocks * kOccluderBlock);
  double* x = z.x_blocks[0].v;
  double* y = z.y_blocks[0].v;
  double* zs = z.z_blocks[0].v;
  uint32_t* slot_sample = z.slot_sample;
  const std::vector<size_t>& tile_block = z.tile_block;
  const std::vector<uint32_t>& tile_samples = z.tile_samples;
  parallelFor(chunks, [&](size_t c) {
    const size_t end = std::min(d.size(), (c + 1) * chunk_size);
    for (size_t i = c * chunk_size; i < end; ++i) {
      const size_t t = grids.tileOf(i);
      const size_t slot = tile_block[t] * kOccluderBlock + chunk_tile[c * tiles + t]++;
      x[slot] = d[i].x;
      y[slot] = d[i].y;
      zs[slot] = d[i].z;
      slot_sample[slot] = uint32_t(i);
    }
  });
  // Padding (a zero sample, never read back), and the farthest sample of every tile.
  std::vector<double>& tile_farthest = z.tile_farthest;
  tile_farthest.assign(tiles, 0.0);
  parallelFor((tiles + kTilesPerItem - 1) / kTilesPerItem, [&](size_t item) {
    const size_t end = std::min(tiles, (item + 1) * kTilesPerItem);
    for (size_t t = item * kTilesPerItem; t < end; ++t) {
      const size_t first = tile_block[t] * kOccluderBlock;
      for (size_t slot = first; slot < first + tile_samples[t]; ++slot) {
        tile_farthest[t] =
            std::max(tile_farthest[t], glm::length(dvec3(x[slot], y[slot], zs[slot])));
      }
      for (size_t slot = first + tile_samples[t]; slot < tile_block[t + 1] * kOccluderBlock;
           ++slot) {
        x[slot] = y[slot] = zs[slot] = 0.0;
        slot_sample[slot] = kNoSample;
      }
    }
  });
  for (const double f : tile_farthest) z.farthest = std::max(z.farthest, f);
}

// The first half of step 3: every triangle set up as an occluder and clipped to the grids in
// parallel chunks of kTrianglesPerChunk; those nearer than the farthest sample get their
// tile ranges, per chunk in triangle order (binned).
void setUpOccluders(const Scene& scene, const std::vector<std::pair<uint32_t, uint32_t>>& where,
                    const Light& light, const IrregularZBuffer& z,
                    std::vector<Occluder>& occluders,
                    std::vector<std::vector<BinnedTriangle>>& binned, Stats& stats) {
  const dvec3 centre(light.center);
  const LightGrids& grids = *z.grids;
  const size_t triangle_count = where.size();
  std::vector<uint64_t> chunk_triangles(binned.size(), 0);
  parallelFor(binned.size(), [&](size_t chunk) {
    const size_t end = std::min(triangle_count, (chunk + 1) * kTrianglesPerChunk);
    for (size_t id = chunk * kTrianglesPerChunk; id < end; ++id) {
      const auto [m, t] = where[id];
      const Mesh& mesh = scene.meshes[m];
      const vec3 a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
      const std::optional<OccluderTest> test = makeOccluderTest(a, b, c, light.center);
      if (!test) continue;
      Occluder& o = occluders[id];
      o.test = *test;
      const dvec3 pa = dvec3(a) - centre, pb = dvec3(b) - centre, pc = dvec3(c) - centre;
      o.nearest = glm::length(closestPointOnTriangle(dvec3(0.0), pa, pb, pc));
      if (o.nearest > z.farthest * (1.0 + kCullMargin)) continue;  // beyond every sample
      bool any = false;
      for (size_t g = 0; g < grids.grids().size(); ++g) {
        TileRange range;
        if (!grids.tileRange(g, pa, pb, pc, range)) continue;
        binned[chunk].push_back({uint32_t(id), uint32_t(g), range});
        any = true;
      }
      chunk_triangles[chunk] += any ? 1 : 0;
    }
  });
  for (const uint64_t n : chunk_triangles) stats.triangles += n;
}

// The second half of step 3: the binned triangles into every tile's list, in triangle order
// (two passes over the same pairs: count, then fill), culled from the tiles whose samples all
// lie nearer to the light than the triangle (the light-space analogue of z-max culling).
void fillOccluderLists(const std::vector<std::vector<BinnedTriangle>>& binned,
                       const IrregularZBuffer& z, AliasFreeOccluderLists& o, Stats& stats) {
  const LightGrids& grids = *z.grids;
  std::vector<size_t>& tile_list = o.tile_list;
  std::vector<size_t> cursor;  // per tile, the next free entry of its list
  // Both passes walk the same pairs in the same order; `fill` is false for the count.
  const auto walk = [&](bool fill) {
    for (const std::vector<BinnedTriangle>& chunk : binned) {
      for (const BinnedTriangle& b : chunk) {
        const LightGrid& g = grids.grids()[b.grid];
        const double nearest = o.occluders[b.triangle].nearest;
        for (int row = b.range.row0; row <= b.range.row1; ++row) {
          for (int column = b.range.column0; column <= b.range.column1; ++column) {
            const size_t t = g.first_tile + size_t(row) * size_t(g.columns) + size_t(column);
            if (z.tile_samples[t] == 0) continue;
            const bool culled = nearest > z.tile_farthest[t] * (1.0 + kCullMargin);
            if (fill) {
              if (!culled) o.lists[cursor[t]++] = b.triangle;
            } else {
              ++stats.tiles_tested;
              if (culled) {
                ++stats.tiles_culled;
              } else {
                ++tile_list[t + 1];
              }
            }
          }
        }
      }
    }
  };
  walk(false);
  for (size_t t = 0; t < z.tiles; ++t) tile_list[t + 1] += tile_list[t];
  o.lists.resize(tile_list[z.tiles]);
  cursor.assign(tile_list.begin(), tile_list.end() - 1);
  walk(true);
}

// 4. Tests, tile by tile (thesis section 4.1: the scene rasterized from the light at the
// irregular sampling points): every triangle of a tile's list against all its samples; a
// sample any of them shadows gets visibility 0. Every sample is one pixel, so tiles write
// disjoint pixels.
void testAliasFreeTiles(const IrregularZBuffer& z, const AliasFreeOccluderLists& o,
                        const std::vector<uint32_t>& sample_pixel, bool simd,
                        Image<float>& visibility, Stats& stats) {
  std::vector<uint64_t> tile_tests(z.tiles, 0);
  parallelFor(z.tiles, [&](size_t t) {
    const size_t first = z.tile_block[t], blocks = z.tile_block[t + 1] - first;
    if (blocks == 0) return;
    std::vector<FlagBlock> shadowed(blocks, FlagBlock{});
    for (size_t k = o.tile_list[t]; k < o.tile_list[t + 1]; ++k) {
      markShadowedSamples(o.occluders[o.lists[k]].test, z.x_blocks[first].v,
                          z.y_blocks[first].v, z.z_blocks[first].v, shadowed[0].v,
                          blocks * kOccluderBlock, simd);
    }
    tile_tests[t] = uint64_t(o.tile_list[t + 1] - o.tile_list[t]) * z.tile_samples[t];
    for (size_t slot = 0; slot < z.tile_samples[t]; ++slot) {
      if (shadowed[slot / kOccluderBlock].v[slot % kOccluderBlock] == 0) continue;
      visibility[sample_pixel[z.slot_sample[first * kOccluderBlock + slot]]] = 0.0f;
    }
  });
  uint64_t sample_tests = 0;
  for (const uint64_t n : tile_tests) sample_tests += n;
  stats.count(kSampleTests, sample_tests);
}

TechniqueResult AliasFree::render(const Light& light, const View& view, const EyeBuffers& eye,
                                  const RenderContext& context) const {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  const int width = eye.depth.width();
  const int height = eye.depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  PENUMBRA_CHECK(eye.primitive.width() == width && eye.primitive.height() == height,
                 "eye primitive ids are {}x{} but the depth buffer is {}x{}",
                 eye.primitive.width(), eye.primitive.height(), width, height);
  const RayOrigins origins(scene_, view);
  origins.checkPrimitiveIds(eye.primitive);

  TechniqueResult result;
  result.visibility.resize(width, height, 1.0f);
  Stats& stats = result.stats;
  stats.count(kLightSamples, 0);  // both counters are reported, zero or not
  stats.count(kSampleTests, 0);
  const dvec3 centre(light.center);

  std::unique_lock<std::mutex> own_scratch(scratch_mutex_, std::try_to_lock);
  Scratch local_scratch;
  Scratch& scratch = own_scratch.owns_lock() ? scratch_ : local_scratch;

  {
    PassTimer timer(stats, "samples");
    gatherAliasFreeSamples(origins, eye, centre, scratch, result.visibility, stats);
  }
  if (scratch.d.empty()) return result;
  IrregularZBuffer z;
  {
    PassTimer timer(stats, "irregular z-buffer");
    buildIrregularZBuffer(scratch.d, options_, scratch, z);
  }
  // 3. Occluders: set up and clipped to the grids in parallel chunks, then binned to tiles in
  // triangle order, so every tile's list is in triangle order.
  AliasFreeOccluderLists occluders;
  occluders.occluders.resize(triangle_count_);
  const size_t chunks = (triangle_count_ + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
  std::vector<std::vector<BinnedTriangle>> binned(chunks);
  occluders.tile_list.assign(z.tiles + 1, 0);
  {
    PassTimer timer(stats, "binning");
    setUpOccluders(scene_, where_, light, z, occluders.occluders, binned, stats);
    fillOccluderLists(binned, z, occluders, stats);
  }
  {
    PassTimer timer(stats, "tests");
    testAliasFreeTiles(z, occluders, scratch.sample_pixel, context.simd, result.visibility,
                       stats);
  }
  return result;
}

}  // namespace

TechniqueInfo aliasFreeTechnique() {
  TechniqueInfo info;
  info.name = "alias-free";
  info.aliases = {"irregular-z-buffer"};
  info.summary = "alias-free shadow map: occluders tested at the eye samples' exact light-space "
                 "positions (irregular z-buffer), hard shadows";
  info.traits.exact = true;
  // The one-ray oracle's answer but for ties on shadow boundaries (tests/test_alias_free.cpp):
  // the same bound as the hard shadow volumes'.
  info.traits.covered_mae_bound = 0.001;
  info.counters = {kLightSamples, kSampleTests};
  info.options =
      OptionTableBuilder<AliasFreeOptions>()
          .integer("tile-samples",
                   "eye samples per light-space tile of the irregular z-buffer, on average",
                   &AliasFreeOptions::tile_samples, 1, 4096)
          .describe([](const AliasFreeOptions& o) {
            return fmt::format("{} samples per light tile", o.tile_samples);
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<AliasFree>(std::any_cast<const AliasFreeOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
