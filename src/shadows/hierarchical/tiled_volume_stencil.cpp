#include "shadows/hierarchical/tiled_volume_stencil.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cfloat>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "core/parallel.h"
#include "raster/binning.h"
#include "raster/cull_tiles.h"
#include "raster/fixed_point.h"
#include "raster/tile_copy.h"
#include "raster/tile_kernels.h"
#include "shadows/hierarchical/tile_box_test.h"
#include "shadows/hierarchical/tile_class_counters.h"
#include "shadows/stages/stencil/stencil_resolve.h"

namespace penumbra {
namespace {

constexpr int kMaxCells = (kBinTileSize / 4) * (kBinTileSize / 4);  // 4x4 tiles

struct VolumeTileWork {
  KernelCounts kernel;
  CullTally tally;
  uint64_t z_reads = 0;  // beyond the kernels': surface ranges of tiles with background
  uint64_t writes = 0;   // beyond the kernels': per-tile counts and their addition to pixels
  uint64_t lit = 0, shadowed = 0, boundary = 0;
  uint64_t accepted = 0;  // boundary tiles a polygon covered and passed whole
};

// A culling tile of a bin tile: its pixels, and the depth range and a sample pixel of its
// surface pixels (none: only background, nothing to shadow). No member initialisers: a bin
// tile holds room for 64 (4x4 tiles) and sets only the ones its tile size uses.
struct Cell {
  int x0, y0, x1, y1;
  bool surface;
  float zmin, zmax;
  int sample_x, sample_y;
  int surface_pixels;  // with surface ranges; otherwise every pixel of a surface cell
};

class BinTile {
 public:
  // With surface_ranges false, tiles holding background keep the depth buffer's range (z-min
  // 0) and no depth is read; otherwise the depths of the tiles with background are read from
  // the frame's buffer.
  BinTile(const TileBox& box, const DepthBuffer& depth, int level, bool surface_ranges,
          VolumeTileWork& work)
      : box_(box), level_(level), per_row_(kBinTileSize >> level) {
    for (int k = 1; k <= per_row_; ++k)
      rows_[k] = rows_[k - 1] | uint64_t(1) << ((k - 1) * per_row_);
    const TileDepthRange& range = depth.tileRange(level);
    const int size = 1 << level;
    for (int cy = 0; cy < per_row_; ++cy)
      for (int cx = 0; cx < per_row_; ++cx) {
        Cell& c = cells_[cy * per_row_ + cx];
        c = Cell{};
        c.x0 = box.x0 + cx * size;
        c.y0 = box.y0 + cy * size;
        c.x1 = std::min(box.x1, c.x0 + size - 1);
        c.y1 = std::min(box.y1, c.y0 + size - 1);
        if (c.x0 > box.x1 || c.y0 > box.y1) continue;
        const float zmin = range.zmin.at(c.x0 >> level, c.y0 >> level);
        const float zmax = range.zmax.at(c.x0 >> level, c.y0 >> level);
        if (zmax <= 0.0f) continue;  // only background
        c.surface = true;
        c.zmax = zmax;
        c.zmin = zmin;
        c.sample_x = c.x0;
        c.sample_y = c.y0;
        c.surface_pixels = (c.x1 - c.x0 + 1) * (c.y1 - c.y0 + 1);
        if (zmin > 0.0f || !surface_ranges) continue;
        // Background pixels (depth 0, infinity) would stretch the box to infinity, where every
        // volume extruded away from the light reaches: the box is taken over the surface
        // pixels only (the stencil is never read on the background), at the cost of reading
        // the tile's depths. The sample is the first surface pixel.
        // Every pixel of the tile is read once; the sample is found by a second look along
        // the first row that has a surface pixel.
        work.z_reads += uint64_t(c.x1 - c.x0 + 1) * uint64_t(c.y1 - c.y0 + 1);
        float lowest = zmax;
        int count = 0;
        bool found = false;
        for (int y = c.y0; y <= c.y1; ++y) {
          const float* row = depth.depth.row(y);
          const int before = count;
          for (int x = c.x0; x <= c.x1; ++x) {
            const float d = row[x];
            count += d > 0.0f ? 1 : 0;
            lowest = std::min(lowest, d > 0.0f ? d : zmax);
          }
          if (found || count == before) continue;
          found = true;
          c.sample_y = y;
          for (c.sample_x = c.x0; !(row[c.sample_x] > 0.0f); ++c.sample_x) {
          }
        }
        c.zmin = lowest;
        c.surface_pixels = count;
      }
    for (int i = 0; i < per_row_ * per_row_; ++i) {
      const Cell& c = cells_[i];
      if (!c.surface) continue;
      if (!any_surface_) sample_ = &c;
      any_surface_ = true;
      surface_mask_ |= uint64_t(1) << i;
      zmin_ = std::min(zmin_, c.zmin);
      zmax_ = std::max(zmax_, c.zmax);
    }
  }
  // The depth range of the bin tile's surface pixels (without surface_ranges, z-min 0 where a
  // tile holds background): its box holds every cell's.
  bool anySurface() const { return any_surface_; }
  // Bit cy * perRow() + cx set for each cell with surface pixels.
  uint64_t surfaceMask() const { return surface_mask_; }
  // A cell with surface pixels, whose sample stands for the whole bin tile.
  const Cell& sampleCell() const { return *sample_; }
  float zmin() const { return zmin_; }
  float zmax() const { return zmax_; }
  int perRow() const { return per_row_; }
  int level() const { return level_; }
  const TileBox& box() const { return box_; }
  const Cell& cell(int cx, int cy) const { return cells_[cy * per_row_ + cx]; }
  const Cell& cell(int i) const { return cells_[i]; }  // bit i of a cell mask
  // Cells the rect's pixels touch, local to the bin tile.
  void cellRange(const TileEdges& e, int& cx0, int& cy0, int& cx1, int& cy1) const {
    cx0 = (e.x0 - box_.x0) >> level_;
    cx1 = (e.x1 - box_.x0) >> level_;
    cy0 = (e.y0 - box_.y0) >> level_;
    cy1 = (e.y1 - box_.y0) >> level_;
  }
  // The cells pixels [x0, x1] x [y0, y1] of the bin tile touch, as bits of surfaceMask()'s
  // layout: the row's bits repeated down the rows by one multiplication (rows_[k] has bit
  // j * perRow() set for every row j < k; the rows' bits do not overlap, so nothing carries).
  uint64_t cellMask(int x0, int y0, int x1, int y1) const {
    const int cx0 = (x0 - box_.x0) >> level_, cx1 = (x1 - box_.x0) >> level_;
    const int cy0 = (y0 - box_.y0) >> level_, cy1 = (y1 - box_.y0) >> level_;
    const uint64_t row = ((uint64_t(2) << cx1) - 1) & ~((uint64_t(1) << cx0) - 1);
    return row * (rows_[cy1 + 1] - rows_[cy0]);
  }
  uint64_t cellMask(const TileEdges& e) const { return cellMask(e.x0, e.y0, e.x1, e.y1); }

 private:
  TileBox box_;
  int level_, per_row_;
  bool any_surface_ = false;
  uint64_t surface_mask_ = 0;
  uint64_t rows_[kBinTileSize / 4 + 1] = {};
  const Cell* sample_ = nullptr;
  float zmin_ = 1.0f, zmax_ = 0.0f;
  Cell cells_[kMaxCells];
};

// A bin tile's depths copied and its stencil zeroed on first use (TileCopy says why a copy):
// most bin tiles that some volume triangle reaches draw no pixel (the volume's depth bounds
// reject the tile, or one sample decides it lit), and such a tile then neither reads 32 rows
// of the frame's depths, one image row apart, nor clears a stencil it would not write.
class LazyTileTarget {
 public:
  // `stencil_buffer`: kBinTileSize^2 elements, left untouched until get().
  LazyTileTarget(const Image<float>& depth, const TileBox& box, int32_t* stencil_buffer)
      : depth_(depth), box_(box) {
    target_.stencil = stencil_buffer;
    target_.stride = kBinTileSize;
    target_.x0 = box.x0;
    target_.y0 = box.y0;
  }
  const StencilTarget& get() {
    if (!depth_copy_) {
      target_.depth = depth_copy_.emplace(depth_, box_).data();
      std::fill_n(target_.stencil, kBinTileSize * kBinTileSize, 0);
    }
    return target_;
  }
  // False while get() has not been called: nothing was drawn, the stencil is all 0.
  bool ready() const { return depth_copy_.has_value(); }

 private:
  const Image<float>& depth_;
  TileBox box_;
  std::optional<TileCopy<float>> depth_copy_;
  StencilTarget target_{};
};

// True when segment (sx0, sy0)-(sx1, sy1) (pixels) meets the rectangle of the pixel centres of
// [x0, x1] x [y0, y1] widened by `slack` pixels: Liang-Barsky clipping, which leaves the part
// inside as the segment's parameters [t0, t1].
bool segmentMeetsRect(double sx0, double sy0, double sx1, double sy1, int x0, int y0, int x1,
                      int y1, double slack, double& t0, double& t1) {
  const double lo[2] = {x0 + 0.5 - slack, y0 + 0.5 - slack};
  const double hi[2] = {x1 + 0.5 + slack, y1 + 0.5 + slack};
  // The segment's bounding box first: most tiles tested lie well away from the segment (a
  // silhouette edge is short on screen, its quad long).
  if (std::max(sx0, sx1) < lo[0] || std::min(sx0, sx1) > hi[0] || std::max(sy0, sy1) < lo[1] ||
      std::min(sy0, sy1) > hi[1])
    return false;
  const double p[2] = {sx0, sy0}, d[2] = {sx1 - sx0, sy1 - sy0};
  t0 = 0.0;
  t1 = 1.0;
  for (int a = 0; a < 2; ++a) {
    if (d[a] == 0.0) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// True when the silhouette segment may meet the tile of pixels [x0, x1] x [y0, y1]: its pixel
// centres' rectangle, widened by 1/8 pixel for the snapping of the drawn edge (1/32 pixel at
// most).
bool segmentMeetsTile(const ScreenSegment& s, int x0, int y0, int x1, int y1) {
  double t0, t1;
  return s.anywhere || segmentMeetsRect(s.x0, s.y0, s.x1, s.y1, x0, y0, x1, y1, 0.125, t0, t1);
}

struct Drawn {
  int32_t contribution;
  DepthRule rule;
};

Drawn drawn(const SetupTriangle& t) {
  const bool zfail = (t.flags & kZFail) != 0;
  return {t.payload * t.facing * (zfail ? -1 : 1),
          zfail ? DepthRule::NotCloser : DepthRule::Closer};
}

// Calls fn(t, e) for each triangle of a volume's run in bin tile `box` with its rect there
// (setupTileRect from the bin tile's origin, as the per-pixel passes: the same float depth at
// every pixel), asking for the records kBinLookahead ahead; stops after a triangle for which fn
// returns false, and returns where the run's rest begins (`last` when it went through).
template <class Fn>
const uint32_t* forEachTileRect(const ShadowVolumeSet& set, const uint32_t* first,
                                const uint32_t* last, const TileBox& box, Fn&& fn) {
  for (const uint32_t* k = first; k != last; ++k) {
    if (last - k > ptrdiff_t(kBinLookahead))
      prefetchSetupTriangle(set.triangles[k[kBinLookahead]]);
    const SetupTriangle& t = set.triangles[*k];
    TileEdges e;
    if (setupTileRect(t, box.x0, box.y0, box.x1, box.y1, e) && !fn(t, e)) return k + 1;
  }
  return last;
}

// Calls fn(k, t, cells) for each triangle t = set.triangles[*k] of a volume's run whose pixel
// box meets the bin tile, with the tiles of its rect there as a cell mask (the rect
// setupTileRect would give, without its depth set-up), asking for the records ahead; stops
// when fn returns false.
template <class Fn>
void forEachRectMask(const ShadowVolumeSet& set, const uint32_t* first, const uint32_t* last,
                     const BinTile& tile, Fn&& fn) {
  const TileBox& box = tile.box();
  for (const uint32_t* k = first; k != last; ++k) {
    if (last - k > ptrdiff_t(kBinLookahead))
      prefetchSetupTriangle(set.triangles[k[kBinLookahead]]);
    const SetupTriangle& t = set.triangles[*k];
    const int x0 = std::max(box.x0, t.min_x), y0 = std::max(box.y0, t.min_y);
    const int x1 = std::min(box.x1, t.max_x), y1 = std::min(box.y1, t.max_y);
    if (x0 > x1 || y0 > y1) continue;
    if (!fn(k, t, tile.cellMask(x0, y0, x1, y1))) return;
  }
}

// The depth bounds test of thesis section 2.2 (Figure 2.3) for volume v: true when a tile whose
// surfaces span [zmin, zmax] counts nothing from the volume. Surfaces all nearer than the whole
// volume: z-pass counts nothing there, z-fail the volume's count at the eye, zero unless the eye
// may be inside; with z-fail, surfaces all farther than the volume count nothing either.
struct DepthBounds {
  DepthBounds(const ShadowVolumeSet& set, size_t v)
      : lo(set.depth_min[v]), hi(set.depth_max[v]), zfail(set.zfail[v] != 0),
        near_test(!zfail || !set.may_contain_eye[v]) {}
  bool rejects(float zmin, float zmax) const {
    return (near_test && zmin > hi) || (zfail && zmax < lo);
  }
  float lo, hi;
  bool zfail, near_test;
};

// The surface tiles of `tile` (as cell bits) whose boxes a face of volume v that vanished in
// set-up may cross (ShadowVolumeSet::vanished): seen edge-on, it crosses no box as a drawn
// triangle would, yet the volume's count can change across it, so one sample cannot decide
// those tiles. A piece wholly in front of or behind a tile's box acts there as a triangle of
// that class covering no pixel centre, which changes no count: a tile counts when the piece's
// part over it (the segment clipped to the tile widened by the slack, its depth range widened
// by the spread and the float margin of tile_box_test.cpp) reaches the box's depths. The
// slivers that set-up drops by the dozen (a volume's far triangles, whose two vertices at
// infinity clip to one guard-band point) lie along their drawn neighbours and rarely do.
uint64_t vanishedCells(const ShadowVolumeSet& set, size_t v, const BinTile& tile) {
  if (set.vanished_begin.empty() || set.vanished_begin[v] == set.vanished_begin[v + 1]) return 0;
  const TileBox& box = tile.box();
  uint64_t cells = 0;
  for (uint32_t k = set.vanished_begin[v]; k < set.vanished_begin[v + 1]; ++k) {
    const VanishedPiece& p = set.vanished[k];
    const int x0 = std::max(box.x0, p.x0), y0 = std::max(box.y0, p.y0);
    const int x1 = std::min(box.x1, p.x1), y1 = std::min(box.y1, p.y1);
    if (x0 > x1 || y0 > y1) continue;
    const double error =
        8.0 * FLT_EPSILON * std::max(std::fabs(p.depth_a), std::fabs(p.depth_b)) + 1e-30;
    for (uint64_t m = tile.cellMask(x0, y0, x1, y1) & tile.surfaceMask(); m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      const Cell& c = tile.cell(i);
      double t0, t1;
      if (!segmentMeetsRect(p.ax, p.ay, p.bx, p.by, c.x0, c.y0, c.x1, c.y1, p.slack, t0, t1))
        continue;
      const double d0 = p.depth_a + t0 * (p.depth_b - p.depth_a);
      const double d1 = p.depth_a + t1 * (p.depth_b - p.depth_a);
      const double margin = p.depth_spread + error;
      if (std::min(d0, d1) - margin <= double(c.zmax) &&
          std::max(d0, d1) + margin >= double(c.zmin))
        cells |= uint64_t(1) << i;
    }
  }
  return cells;
}

// Depth bounds: the volume's triangles drawn per pixel in the tiles that neither the ordinary
// depth-rule test (rasterizer.cpp: depthRuleTiles) nor the volume's bounds reject.
void drawDepthBounded(const ShadowVolumeSet& set, size_t v, const uint32_t* first,
                      const uint32_t* last, const BinTile& tile, const DepthBuffer& depth,
                      LazyTileTarget& target, bool simd, VolumeTileWork& work) {
  const DepthBounds bounds(set, v);
  const bool zfail = bounds.zfail;
  // The test for the whole bin tile first: when it rejects the volume, no triangle of it is set
  // up here (forEachCullRect would reject each on the same range).
  if (bounds.rejects(tile.zmin(), tile.zmax())) return;
  forEachTileRect(set, first, last, tile.box(), [&](const SetupTriangle& t, TileEdges& e) {
    const Drawn d = drawn(t);
    forEachCullRect(
        t, e, depth, tile.level(),
        [&](const TileEdges& sub, float zmin, float zmax) {
          if (bounds.rejects(zmin, zmax)) return 0;
          return depthRuleTiles(t, sub, zfail, zmin, zmax, false) == DepthRuleTiles::None ? 0
                                                                                         : 1;
        },
        [&](const TileEdges& rect, int) {
          stencilKernel(rect, d.contribution, d.rule, target.get(), work.kernel, simd);
        },
        work.tally);
    return true;
  });
}

// A volume triangle's rect in a bin tile, set up once, with its class against the bin tile's
// box: kept from the classification for the tile walk and the drawing.
struct HierarchicalRect {
  const SetupTriangle* t;
  TileEdges e;
  TileBoxClass whole;
};

// The hierarchical rendering of one shadow volume in one bin tile (thesis section 4.3, Figure
// 4.3): classify the volume's tiles, decide the inner ones by one sample each, draw the
// potential boundary tiles per pixel; the decided counts are added to `coarse` (one per tile).
// One object per volume and bin tile; its steps share the tile masks below.
class HierarchicalVolumeDraw {
 public:
  HierarchicalVolumeDraw(const ShadowVolumeSet& set, size_t v, const uint32_t* first,
                         const uint32_t* last, const BinTile& tile, const DepthBuffer& depth,
                         LazyTileTarget& target, const TiledVolumeStencilOptions& options,
                         int32_t* coarse, VolumeTileWork& work,
                         std::vector<HierarchicalRect>& rects)
      : set_(set), v_(v), first_(first), last_(last), tile_(tile), depth_(depth),
        target_(target), coarse_(coarse), work_(work), rects_(rects), bounds_(set, v),
        box_(tile.box()), simd_(options.simd), zfail_(set.zfail[v] != 0), n_(tile.perRow()),
        // A volume dense here is not classified triangle by tile
        // (TiledVolumeStencilOptions::dense_limit).
        dense_(options.dense_limit > 0 &&
               last - first > ptrdiff_t(options.dense_limit) * kAreasPerBinTile),
        // A z-pass volume the eye may be inside is open on screen: no tile of it is decided
        // by one sample (volume_set.h: may_contain_eye).
        open_(!zfail_ && set.may_contain_eye[v] != 0),
        counted_(zfail_ ? TileBoxClass::Behind : TileBoxClass::Front),
        // Wholly on the other side of a box, a triangle fails the depth rule at every surface
        // pixel in it (z-pass counts what lies in front, z-fail what lies behind): drawn, it
        // would only be culled or rasterized without a write.
        never_(zfail_ ? TileBoxClass::Front : TileBoxClass::Behind),
        surface_(tile.surfaceMask()) {}

  void run() {
    // The depth bounds test for the whole bin tile first (drawDepthBounded): surfaces all
    // nearer than the volume (where that is allowed) or, with z-fail, all farther count
    // nothing from it.
    if (bounds_.rejects(tile_.zmin(), tile_.zmax())) return;
    // Tiles that a face seen edge-on reaches: never decided by a sample (vanishedCells).
    edge_on_ = vanishedCells(set_, v_, tile_);
    rects_.clear();
    if (dense_ && !open_ && decideDenseBinTile()) return;
    if (open_ || dense_) return drawUnclassified();
    // With tiles as large as the bin tile, the first triangle that crosses makes it a boundary
    // tile: the rest of the run is drawn without a test (`rest`).
    const bool bin_level = tile_.level() == kBinTileLevel;
    bool any_crossing = false;
    const uint32_t* rest = classifyAgainstBinTile(bin_level, any_crossing);
    if (!any_crossing && edge_on_ == 0) return decideBinTileBySample();
    if (bin_level) return drawBinLevelBoundary(rest);
    classifyTiles();
    if (boundary_ == 0) return;
    for (HierarchicalRect& r : rects_)
      if (r.whole != never_) draw(*r.t, r.e);
  }

 private:
  static constexpr ptrdiff_t kAreasPerBinTile = (kBinTileSize / 8) * (kBinTileSize / 8);  // 8x8
  // The boundary tiles drawn per pixel as the per-pixel passes draw (rasterizer.cpp): the
  // depth-rule test per tile from its z-min and z-max culls the tiles no pixel of which can
  // pass, and a polygon covering a whole tile and passing at every pixel of it adds to the
  // tile's count instead (the z-min trivial accept, thesis section 1.5).
  static constexpr int kDraw = 1, kWhole = 2;

  int depthRule(const SetupTriangle& t, const TileEdges& sub, float zmin, float zmax) const {
    switch (depthRuleTiles(t, sub, zfail_, zmin, zmax, true)) {
      case DepthRuleTiles::None: return 0;
      case DepthRuleTiles::Some: return kDraw;
      case DepthRuleTiles::All: return kDraw | kWhole;
    }
    return kDraw;
  }

  void drawRect(const Drawn& d, const TileEdges& rect, int code) {
    if (!(code & kWhole)) {
      stencilKernel(rect, d.contribution, d.rule, target_.get(), work_.kernel, simd_);
      return;
    }
    int cx0, cy0, cx1, cy1;
    tile_.cellRange(rect, cx0, cy0, cx1, cy1);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        coarse_[cy * n_ + cx] += d.contribution;
        ++work_.writes;
        ++work_.accepted;
      }
  }

  // The per-pixel step of section 4.3 for one triangle: drawn in the boundary tiles.
  void draw(const SetupTriangle& t, TileEdges& e) {
    const Drawn d = drawn(t);
    // A triangle whose rect reaches no decided tile is drawn over its whole rect, tested per
    // bin tile as the per-pixel passes do (one depth-rule test and one kernel call instead of
    // one per tile); outside the boundary tiles it covers no pixel with a surface
    // (classifyTileBox found it Outside there, or the tile holds only background). The level
    // is a constant there, so the culling walk compiles to the per-pixel passes' one test
    // (with the level a variable, the volumes drawn per pixel took 6 % longer on fractal).
    if (decided_ == 0 || (tile_.cellMask(e) & decided_) == 0) {
      forEachCullRect(
          t, e, depth_, kBinTileLevel,
          [&](const TileEdges& sub, float zmin, float zmax) {
            return depthRule(t, sub, zmin, zmax);
          },
          [&](const TileEdges& rect, int code) { drawRect(d, rect, code); }, work_.tally,
          kWhole);
      return;
    }
    // Otherwise tile by tile, skipping the decided ones.
    forEachCullRect(
        t, e, depth_, tile_.level(),
        [&](const TileEdges& sub, float zmin, float zmax) {
          // (The boundary tiles passed the depth bounds test, as the whole bin tile did.)
          if ((tile_.cellMask(sub) & boundary_) == 0) return 0;
          return depthRule(t, sub, zmin, zmax);
        },
        [&](const TileEdges& rect, int code) { drawRect(d, rect, code); }, work_.tally, kWhole);
  }

  // A triangle drawn unclassified, unless its whole depth range lies on the side that never
  // counts.
  void drawCounting(const SetupTriangle& t) {
    if (classifyDepthRange(t, tile_.zmin(), tile_.zmax()) == never_) return;
    TileEdges e;
    if (setupTileRect(t, box_.x0, box_.y0, box_.x1, box_.y1, e)) draw(t, e);
  }

  // z-pass leaves the light caps out, so across a silhouette edge the drawn count changes where
  // the quad is counted (Front): such a tile is decided per pixel.
  bool silhouetteMeets(const SetupTriangle& t, int x0, int y0, int x1, int y1) const {
    return !zfail_ && t.owners[0] != ClipTriangles::kNoOwner &&
           segmentMeetsTile(set_.silhouettes[t.owners[0]], x0, y0, x1, y1);
  }

  // The count of every surface pixel of the bin tile, all of them given by one sample, added
  // to the tiles `reached` (the rects' tiles; the lit and shadowed counts are theirs).
  void decideBinTile(uint64_t reached, int32_t count) {
    reached &= surface_;
    const uint64_t cells = uint64_t(std::popcount(reached));
    if (count == 0) {
      work_.lit += cells;
      return;
    }
    work_.shadowed += cells;
    work_.writes += cells;  // the per-tile counts
    for (; reached != 0; reached &= reached - 1) coarse_[std::countr_zero(reached)] += count;
  }

  // A dense volume is not classified triangle by tile, but its triangles' whole depth ranges
  // (two comparisons each) may still show that none crosses the bin tile's box: all in front
  // of its surfaces or behind them. Then one sample decides the bin tile (true), as in
  // decideBinTileBySample. The first triangle that may cross ends the test: the volume is drawn
  // per pixel (false).
  bool decideDenseBinTile() {
    const Cell& s = tile_.sampleCell();
    uint64_t reached = 0;
    int32_t count = 0;
    bool crossing = false;
    forEachRectMask(set_, first_, last_, tile_, [&](const uint32_t*, const SetupTriangle& t,
                                                    uint64_t cells) {
      ++work_.tally.tested;
      TileBoxClass whole = classifyDepthRange(t, tile_.zmin(), tile_.zmax());
      if (whole == TileBoxClass::Front && silhouetteMeets(t, box_.x0, box_.y0, box_.x1, box_.y1))
        whole = TileBoxClass::Crossing;
      crossing = whole == TileBoxClass::Crossing;
      reached |= cells;
      if (whole == counted_ && coversPixel(t, s.sample_x, s.sample_y))
        count += drawn(t).contribution;
      return !crossing;
    });
    if (crossing || edge_on_ != 0) return false;
    decideBinTile(reached, count);
    return true;
  }

  // Unclassified (open or dense volumes): the boundary tiles are the surface tiles the
  // triangles' rects reach. Nothing is drawn until a triangle reaches one (a volume over only
  // background here draws nothing); the triangles before it are then drawn first (the stencil
  // is a sum: the order does not matter).
  void drawUnclassified() {
    uint64_t reached = 0;
    const uint32_t* pending = first_;  // the triangles before it are drawn
    forEachRectMask(set_, first_, last_, tile_, [&](const uint32_t* k, const SetupTriangle& t,
                                                    uint64_t cells) {
      reached |= cells;
      if ((reached & surface_) == 0) return true;
      for (; pending != k; ++pending) drawCounting(set_.triangles[*pending]);
      pending = k + 1;
      drawCounting(t);
      return true;
    });
    boundary_ = reached & surface_;
    work_.boundary += uint64_t(std::popcount(boundary_));
  }

  // The classification to potential boundary tiles (section 4.3), first for the bin tile: each
  // triangle against the box of its whole rect's pixels and the bin tile's surface range. Each
  // smaller tile's box lies inside it, so an answer other than Crossing holds for every tile of
  // the rect (which is then classified without a test of its own: the sample decides). Keeps
  // the rects in rects_; returns where the run's rest begins (with bin_level, after the first
  // crossing triangle).
  const uint32_t* classifyAgainstBinTile(bool bin_level, bool& any_crossing) {
    return forEachTileRect(set_, first_, last_, box_, [&](const SetupTriangle& t, TileEdges& e) {
      ++work_.tally.tested;
      TileBoxClass whole =
          classifyTileBox(t, e.x0, e.y0, e.x1, e.y1, tile_.zmin(), tile_.zmax());
      // The count changes across a silhouette edge on both of its sides, beyond the rect of
      // the quad that holds it: the edge is tested against the whole bin tile.
      if (whole == TileBoxClass::Front && silhouetteMeets(t, box_.x0, box_.y0, box_.x1, box_.y1))
        whole = TileBoxClass::Crossing;  // decide tile by tile
      if (whole == TileBoxClass::Outside) {
        ++work_.tally.culled;
        return true;  // no pixel centre of the bin tile under it
      }
      any_crossing |= whole == TileBoxClass::Crossing;
      rects_.push_back({&t, e, whole});
      return !(bin_level && any_crossing);
    });
  }

  // No triangle crosses the bin tile's box: the box, convex, lies wholly inside or wholly
  // outside the volume, so every surface pixel of the bin tile has one count, the sample's
  // (section 4.3's argument for a tile, made for the bin tile; z-pass's open silhouette edges
  // made their quads Crossing, and a face seen edge-on, which set-up dropped, keeps the tiles
  // it reaches from being decided). Each tile a rect reaches is decided with that count, as
  // the tile-by-tile walk (classifyTiles) would decide it: its classes would all be inherited,
  // and its samples would find the same count. One walk over the rects instead of one per
  // tile.
  void decideBinTileBySample() {
    const Cell& s = tile_.sampleCell();
    uint64_t reached = 0;
    int32_t count = 0;
    for (const HierarchicalRect& r : rects_) {
      reached |= tile_.cellMask(r.e);
      if (r.whole == counted_ && coversPixel(*r.t, s.sample_x, s.sample_y))
        count += drawn(*r.t).contribution;
    }
    decideBinTile(reached, count);
  }

  // Tiles as large as the bin tile: the one tile's box is the box just tested, so a triangle
  // crossing it crosses the tile, and the tile is a boundary tile (as it is when a face seen
  // edge-on reaches it), drawn per pixel: the rects kept, then the run's rest unclassified.
  void drawBinLevelBoundary(const uint32_t* rest) {
    boundary_ = surface_;
    work_.boundary += uint64_t(std::popcount(boundary_));
    for (HierarchicalRect& r : rects_)
      if (r.whole != never_) draw(*r.t, r.e);
    for (; rest != last_; ++rest) {
      if (last_ - rest > ptrdiff_t(kBinLookahead))
        prefetchSetupTriangle(set_.triangles[rest[kBinLookahead]]);
      drawCounting(set_.triangles[*rest]);
    }
  }

  // The classification to potential boundary tiles tile by tile (section 4.3), and the
  // decision of the others by their sample: the rects crossing the bin tile's box are tested
  // per tile (a tile found a boundary tile by an earlier rect is not tested again); the others
  // take their class over every tile they reach. Sets boundary_ and decided_.
  void classifyTiles() {
    int32_t sample[kMaxCells];
    std::fill_n(sample, n_ * n_, 0);
    // Tiles a face seen edge-on reaches are boundary tiles where some rect reaches them.
    if (edge_on_ != 0)
      for (const HierarchicalRect& r : rects_) boundary_ |= tile_.cellMask(r.e) & edge_on_;
    uint64_t touched = 0;
    for (const HierarchicalRect& r : rects_) {
      const uint64_t reached = tile_.cellMask(r.e) & surface_;
      if (r.whole != TileBoxClass::Crossing) {
        touched |= reached;
        continue;
      }
      classifyCrossingRect(*r.t, reached, touched, sample);
    }
    // The depth bounds test per tile (thesis section 2.2), for the volume as a whole: a
    // boundary tile whose surfaces it rejects counts nothing from the volume (DepthBounds), so
    // it is decided, lit. Taken per triangle while drawing, the test would skip the triangles
    // drawn tile by tile there but not those drawn over their whole rect (draw): a partial sum,
    // wrong wherever the skipped ones do not cancel (a tile made a boundary tile by a face seen
    // edge-on need not overlap the volume's depth range at all).
    uint64_t rejected = 0;
    for (uint64_t m = boundary_; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (bounds_.rejects(tile_.cell(i).zmin, tile_.cell(i).zmax)) rejected |= uint64_t(1) << i;
    }
    boundary_ &= ~rejected;
    // The samples of the rects counted over every tile they reach, now that the tiles left to
    // decide are known.
    decided_ = (touched | rejected) & ~boundary_;
    for (const HierarchicalRect& r : rects_) {
      if (r.whole != counted_) continue;
      const int32_t contribution = drawn(*r.t).contribution;
      for (uint64_t m = tile_.cellMask(r.e) & decided_; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        const Cell& c = tile_.cell(i);
        if (coversPixel(*r.t, c.sample_x, c.sample_y)) sample[i] += contribution;
      }
    }
    for (uint64_t m = rejected; m != 0; m &= m - 1) sample[std::countr_zero(m)] = 0;
    work_.boundary += uint64_t(std::popcount(boundary_));
    decideTilesBySample(sample);
  }

  // One triangle crossing the bin tile's box, classified against each surface tile it reaches
  // that is not yet a boundary tile: a crossing tile (or, with z-pass, one its silhouette edge
  // meets) becomes a boundary tile; a tile it covers from the counted side at its sample adds
  // its contribution there.
  void classifyCrossingRect(const SetupTriangle& t, uint64_t reached, uint64_t& touched,
                            int32_t* sample) {
    const int32_t contribution = drawn(t).contribution;
    for (uint64_t m = reached & ~boundary_; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      const Cell& c = tile_.cell(i);
      ++work_.tally.tested;
      const TileBoxClass cls = classifyTileBox(t, c.x0, c.y0, c.x1, c.y1, c.zmin, c.zmax);
      if (cls == TileBoxClass::Outside) {
        ++work_.tally.culled;
        continue;
      }
      touched |= uint64_t(1) << i;
      if (cls == TileBoxClass::Crossing ||
          (cls == TileBoxClass::Front && silhouetteMeets(t, c.x0, c.y0, c.x1, c.y1))) {
        boundary_ |= uint64_t(1) << i;
      } else if (cls == counted_ && coversPixel(t, c.sample_x, c.sample_y)) {
        sample[i] += contribution;
      }
    }
  }

  // The decided tiles take their sample's count (thesis section 4.3, Figure 4.3 b): a non-zero
  // count is added to the tile's count, shadowed; zero leaves it lit.
  void decideTilesBySample(const int32_t* sample) {
    for (uint64_t m = decided_; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (sample[i] != 0) {
        ++work_.shadowed;
        ++work_.writes;  // the per-tile count
        coarse_[i] += sample[i];
      } else {
        ++work_.lit;
      }
    }
  }

  const ShadowVolumeSet& set_;
  size_t v_;
  const uint32_t *first_, *last_;
  const BinTile& tile_;
  const DepthBuffer& depth_;
  LazyTileTarget& target_;
  int32_t* coarse_;
  VolumeTileWork& work_;
  std::vector<HierarchicalRect>& rects_;
  const DepthBounds bounds_;
  const TileBox& box_;
  const bool simd_, zfail_;
  const int n_;
  const bool dense_, open_;
  const TileBoxClass counted_, never_;
  const uint64_t surface_;
  uint64_t edge_on_ = 0;
  // Tiles as bits (BinTile::cellMask): those drawn per pixel, and those decided by a sample.
  uint64_t boundary_ = 0, decided_ = 0;
};

// Hierarchical (thesis section 4.3): classify the volume's tiles, decide the inner ones by
// their sample, draw the boundary ones per pixel. Adds the decided counts to `coarse`.
void drawHierarchical(const ShadowVolumeSet& set, size_t v, const uint32_t* first,
                      const uint32_t* last, const BinTile& tile, const DepthBuffer& depth,
                      LazyTileTarget& target, const TiledVolumeStencilOptions& options,
                      int32_t* coarse, VolumeTileWork& work) {
  thread_local std::vector<HierarchicalRect> rects;  // one buffer per thread
  HierarchicalVolumeDraw(set, v, first, last, tile, depth, target, options, coarse, work, rects)
      .run();
}

TileBox binTileBox(const TileBins& bins, size_t tile, int width, int height) {
  const int tx = int(tile % size_t(bins.tiles_x)), ty = int(tile / size_t(bins.tiles_x));
  const int x0 = tx * kBinTileSize, y0 = ty * kBinTileSize;
  return {x0, y0, std::min(width, x0 + kBinTileSize) - 1, std::min(height, y0 + kBinTileSize) - 1};
}

// Draws bin tile `index`'s volumes into `stencil_buffer` (kBinTileSize pixels per row, taken as
// it is) over a copy of the tile's depths, both set up only when a pixel or a tile's count is
// drawn (LazyTileTarget); false when nothing was (no triangle, only background, or every volume
// culled or decided lit there): the buffer is then untouched and the tile's stencil is all 0.
bool drawBinTile(const ShadowVolumeSet& set, const DepthBuffer& depth,
                 const TiledVolumeStencilOptions& options, const TileBins& bins, size_t index,
                 const TileBox& box, int32_t* stencil_buffer, VolumeTileWork& w) {
  const uint32_t* first = bins.triangles.data() + bins.offsets[index];
  const uint32_t* last = bins.triangles.data() + bins.offsets[index + 1];
  if (first == last) return false;
  LazyTileTarget target(depth.depth, box, stencil_buffer);
  const bool hierarchical = options.culling == VolumeCulling::Hierarchical;
  // The surface ranges of tiles with background are only needed (and read) by Hierarchical.
  const BinTile tile(box, depth, options.tile_level, hierarchical, w);
  if (!tile.anySurface()) return false;  // only background: the stencil stays 0
  int32_t coarse[kMaxCells] = {};
  // The bin's triangles are in increasing order, so each volume's are one run, found by binary
  // search (a dense volume's run holds hundreds of triangles, a scene may hold thousands of
  // volumes).
  while (first != last) {
    const auto after = std::upper_bound(set.begin.begin(), set.begin.end(), *first);
    const size_t v = size_t(after - set.begin.begin()) - 1;
    const uint32_t* end = std::lower_bound(first, last, set.begin[v + 1]);
    if (hierarchical)
      drawHierarchical(set, v, first, end, tile, depth, target, options, coarse, w);
    else
      drawDepthBounded(set, v, first, end, tile, depth, target, options.simd, w);
    first = end;
  }
  if (hierarchical) {
    // The per-tile counts added to their surface pixels (background keeps 0), branch-free so
    // that the row vectorizes; each surface pixel a non-zero count reaches is one stencil
    // write.
    const int n = tile.perRow();
    for (int cy = 0; cy < n; ++cy)
      for (int cx = 0; cx < n; ++cx) {
        const int32_t sum = coarse[cy * n + cx];
        if (sum == 0) continue;
        const StencilTarget& t = target.get();
        const Cell& c = tile.cell(cx, cy);
        const int x0 = c.x0 - box.x0, x1 = c.x1 - box.x0;
        const bool all_surface = c.surface_pixels == (x1 - x0 + 1) * (c.y1 - c.y0 + 1);
        for (int y = c.y0; y <= c.y1; ++y) {
          const size_t row = size_t(y - box.y0) * kBinTileSize;
          const float* d = t.depth + row;
          int32_t* s = t.stencil + row;
          if (all_surface) {
            for (int i = x0; i <= x1; ++i) s[i] += sum;
          } else {
            for (int i = x0; i <= x1; ++i) s[i] += d[i] > 0.0f ? sum : 0;
          }
        }
        w.writes += uint64_t(c.surface_pixels);
      }
  }
  return target.ready();
}

void addCounters(const std::vector<VolumeTileWork>& work, const TiledVolumeStencilOptions& options,
                 Stats& stats) {
  const bool hierarchical = options.culling == VolumeCulling::Hierarchical;
  uint64_t lit = 0, shadowed = 0, boundary = 0;
  for (const VolumeTileWork& w : work) {
    stats.pixels_rasterized += w.kernel.covered;
    stats.z_reads += w.kernel.covered + w.z_reads;
    stats.stencil_writes += w.kernel.writes + w.writes;
    stats.tiles_tested += w.tally.tested;
    stats.tiles_culled += w.tally.culled;
    stats.tiles_accepted += w.accepted;
    lit += w.lit;
    shadowed += w.shadowed;
    boundary += w.boundary;
  }
  if (!hierarchical) return;
  stats.count(kTilesLit, lit);
  stats.count(kTilesShadowed, shadowed);
  stats.count(kTilesBoundary, boundary);
}

void checkLevel(const TiledVolumeStencilOptions& options) {
  PENUMBRA_CHECK(options.tile_level >= 2 && options.tile_level <= kBinTileLevel,
                 "tile level {} is outside 2..{}", options.tile_level, kBinTileLevel);
}

}  // namespace

Image<int32_t> tiledVolumeStencil(const ShadowVolumeSet& set, const DepthBuffer& depth,
                                  const TiledVolumeStencilOptions& options, Stats& stats) {
  checkLevel(options);
  const int width = depth.width(), height = depth.height();
  Image<int32_t> stencil(width, height, 0);
  const TileBins bins = binTriangles(set.triangles, width, height);
  std::vector<VolumeTileWork> work(bins.tileCount());
  parallelFor(bins.tileCount(), [&](size_t index) {
    if (bins.offsets[index] == bins.offsets[index + 1]) return;
    const TileBox box = binTileBox(bins, index, width, height);
    TileCopy<int32_t> tile_stencil;
    if (drawBinTile(set, depth, options, bins, index, box, tile_stencil.data(), work[index]))
      tile_stencil.storeTo(stencil, box);
  });
  addCounters(work, options, stats);
  return stencil;
}

void tiledVolumeVisibility(const ShadowVolumeSet& set, const EyeBuffers& eye,
                           const FacingAway& away, const TiledVolumeStencilOptions& options,
                           Image<float>& visibility, Stats& stats) {
  checkLevel(options);
  const DepthBuffer& depth = eye.depth;
  const int width = depth.width(), height = depth.height();
  PENUMBRA_CHECK(eye.primitive.width() == width && eye.primitive.height() == height,
                 "primitive ids {}x{} do not match depth {}x{}", eye.primitive.width(),
                 eye.primitive.height(), width, height);
  visibility.resizeForOverwrite(width, height);
  const TileBins bins = binTriangles(set.triangles, width, height);
  std::vector<VolumeTileWork> work(bins.tileCount());
  // Each bin tile some volume triangle reaches draws into a stencil slot of its own; the
  // visibility is resolved a row of bin tiles at a time, along the image's rows, by the worker
  // that finishes the row's last tile (no second parallel pass to wait for). Resolved tile by
  // tile instead, each tile's 32-pixel pieces of rows one image row apart took about 2.8 times
  // as long per pixel as the per-pixel technique's resolve along whole rows (bench/README.md).
  // Tiles that wrote no stencil (no triangle, or all culled by the depth bounds or decided
  // lit) are resolved with stencil 0, a run of them at a time: most of a frame where the
  // shadows are small (at 1920x1080 on spheres, 1,790 of 2,040).
  const size_t tiles_x = size_t(bins.tiles_x);
  // Tile i's stencil slot is row i, set only where the tile wrote (untouched memory elsewhere).
  Image<int32_t> stencils;
  stencils.resizeForOverwrite(kBinTileSize * kBinTileSize, int(bins.tileCount()));
  std::vector<uint8_t> written(bins.tileCount(), 0);
  std::unique_ptr<std::atomic<int>[]> row_left(new std::atomic<int>[size_t(bins.tiles_y)]);
  for (int ty = 0; ty < bins.tiles_y; ++ty) row_left[size_t(ty)].store(bins.tiles_x);
  auto resolveTileRow = [&](size_t ty) {
    const int y0 = int(ty) * kBinTileSize, y1 = std::min(height, y0 + kBinTileSize) - 1;
    const size_t first_tile = ty * tiles_x;
    std::vector<StencilSegment> segments;
    segments.reserve(tiles_x);
    for (int tx = 0; tx < bins.tiles_x;) {
      const int x0 = tx * kBinTileSize;
      const size_t tile = first_tile + size_t(tx);
      if (written[tile]) {
        const int x1 = std::min(width, x0 + kBinTileSize) - 1;
        segments.push_back({x0, x1 - x0 + 1, stencils.row(int(tile)), kBinTileSize});
        ++tx;
        continue;
      }
      while (tx < bins.tiles_x && !written[first_tile + size_t(tx)]) ++tx;
      const int x1 = std::min(width, tx * kBinTileSize) - 1;
      segments.push_back({x0, x1 - x0 + 1, nullptr, 0});
    }
    resolveStencilRows(away,
                       {eye.primitive.row(y0), size_t(width), visibility.row(y0), size_t(width),
                        y1 - y0 + 1, segments.data(), segments.size()},
                       options.simd);
  };
  parallelFor(bins.tileCount(), [&](size_t index) {
    if (bins.offsets[index] != bins.offsets[index + 1]) {
      const TileBox box = binTileBox(bins, index, width, height);
      written[index] =
          drawBinTile(set, depth, options, bins, index, box, stencils.row(int(index)), work[index])
              ? 1
              : 0;
    }
    // The row's flags and slots are written before the count drops (release) and read by the
    // worker that brings it to 0 (acquire).
    const size_t ty = index / tiles_x;
    if (row_left[ty].fetch_sub(1, std::memory_order_acq_rel) == 1) resolveTileRow(ty);
  });
  addCounters(work, options, stats);
}

}  // namespace penumbra
