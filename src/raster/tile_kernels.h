#pragma once
// Per-(triangle, tile) pixel kernels: the hot loops of every pass. Each kernel has a SIMD
// version (Highway, 4 to 16 pixels per step, dispatched at run time) and a scalar twin that
// follows the same steps and must give bit-identical buffers and counts (tests check it).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/simd_dispatch.h"
#include "raster/triangle_setup.h"

namespace penumbra {

// A triangle's edge functions and depth restricted to one tile, in int32 and float.
// Pixel (x, y) of the rect is inside iff for all i: e0[i] + dx[i] (x - tx0) + dy[i] (y - ty0) >= 0
// (edges the whole rect is inside of are folded to e0 = dx = dy = 0). Its depth is
//   (dc + db * float(y - ty0)) + da * float(x - tx0)
// evaluated in exactly this order in both twins (no FMA: the build passes -ffp-contract=off).
struct TileEdges {
  int32_t e0[3], dx[3], dy[3];
  float dc, da, db;
  int tx0, ty0;          // tile origin pixel
  int x0, y0, x1, y1;    // pixels to visit, inclusive: triangle box within the tile
};

// The columns of one row of a rect worth visiting: those where every edge can be >= 0. Per edge
// the inside columns are a half-line, solved in double and rounded outwards, so [x_lo, x_hi]
// holds every covered pixel and at most one uncovered pixel at either end (the SIMD kernels
// still test every pixel: the span only skips vectors that would find none inside). Shadow
// volume quads and wedge faces are long and slanted: over their whole rects, most SIMD steps
// of the umbra pass would find no pixel inside (bench/README.md).
class RowSpans {
 public:
  explicit RowSpans(const TileEdges& e) : e_(e) {
    for (int i = 0; i < 3; ++i) inverse_dx_[i] = e.dx[i] != 0 ? 1.0 / double(e.dx[i]) : 0.0;
  }
  // The rows [y_lo, y_hi] within [e.y0, e.y1] outside which no row holds a covered pixel (false:
  // none does). The rect is the triangle's box within a tile, and a long slanted triangle
  // crosses only a band of it: most rows of the umbra pass's rects have an empty span
  // (bench/README.md), each costing a span() call. Per edge with dx != 0 the column where it
  // is 0 is linear in the row, z(ry) = (-e0 - dy ry) / dx: a covered pixel lies right of every
  // such z with dx > 0 and of the rect's first column, left of every z with dx < 0 and of its
  // last column. Each (left bound, right bound) pair is linear in the row, so the rows where it
  // leaves room, with a pixel of slack for rounding, form a half-line; edges with dx = 0 bound
  // the rows directly.
  bool rows(int& y_lo, int& y_hi) const {
    double first = double(e_.y0 - e_.ty0), last = double(e_.y1 - e_.ty0);
    // Bounds z = a + b ry: [0] the rect's column, then the edges'.
    double lo_a[4] = {double(e_.x0 - e_.tx0)}, lo_b[4] = {0.0};
    double hi_a[4] = {double(e_.x1 - e_.tx0)}, hi_b[4] = {0.0};
    int lo_n = 1, hi_n = 1;
    for (int i = 0; i < 3; ++i) {
      if (e_.dx[i] == 0) {  // e0 + dy ry >= 0 (a folded edge, e0 = dy = 0, always holds)
        if (e_.dy[i] > 0) {
          first = std::max(first, std::floor(-double(e_.e0[i]) / double(e_.dy[i])));
        } else if (e_.dy[i] < 0) {
          last = std::min(last, std::ceil(double(e_.e0[i]) / -double(e_.dy[i])));
        } else if (e_.e0[i] < 0) {
          return false;
        }
        continue;
      }
      const double a = -double(e_.e0[i]) * inverse_dx_[i], b = -double(e_.dy[i]) * inverse_dx_[i];
      if (e_.dx[i] > 0) {
        lo_a[lo_n] = a;
        lo_b[lo_n++] = b;
      } else {
        hi_a[hi_n] = a;
        hi_b[hi_n++] = b;
      }
    }
    for (int h = 0; h < hi_n; ++h)
      for (int l = 0; l < lo_n; ++l) {
        // (hi - lo)(ry) + 1 = c + d ry >= 0.
        const double c = hi_a[h] - lo_a[l] + 1.0, d = hi_b[h] - lo_b[l];
        if (d == 0.0) {
          if (c < 0.0) return false;
        } else if (d > 0.0) {
          first = std::max(first, std::floor(-c / d));
        } else {
          last = std::min(last, std::ceil(-c / d));
        }
      }
    if (!(first <= last)) return false;
    y_lo = e_.ty0 + int(first);
    y_hi = e_.ty0 + int(last);
    return true;
  }
  // 1 / dx per edge (0 where dx is 0) and the rect, for the batched form (row_spans_simd-inl.h).
  const double* inverseDx() const { return inverse_dx_; }
  const TileEdges& edges() const { return e_; }
  // Row whose edge values at the tile origin's column are r[]: false when no pixel of it can
  // be inside, else the image columns [x_lo, x_hi] within [e.x0, e.x1].
  bool span(const int32_t (&r)[3], int& x_lo, int& x_hi) const {
    double lo = double(e_.x0 - e_.tx0), hi = double(e_.x1 - e_.tx0);
    for (int i = 0; i < 3; ++i) {
      if (e_.dx[i] == 0) {
        if (r[i] < 0) return false;
        continue;
      }
      const double zero = -double(r[i]) * inverse_dx_[i];  // where the edge value is 0
      if (e_.dx[i] > 0)
        lo = std::max(lo, std::floor(zero));
      else
        hi = std::min(hi, std::ceil(zero));
    }
    if (!(lo <= hi)) return false;
    x_lo = e_.tx0 + int(lo);
    x_hi = e_.tx0 + int(hi);
    return true;
  }

 private:
  const TileEdges& e_;
  double inverse_dx_[3];
};

// RowSpans::span for rows y0 .. y0 + count - 1 of e's rect, count <= kRowSpanBatch: x_lo[k],
// x_hi[k] (image columns) for row y0 + k, or x_lo[k] = e.tx0 + 1 > x_hi[k] = e.tx0 where span()
// finds no pixel. The SIMD kernels find their rows' spans this way, several rows per SIMD step
// (raster/row_spans_simd-inl.h); the arrays need kRowSpanArray entries (a last SIMD step may
// run past `count`). The scalar twin calls span() row by row; tests hold the two equal.
inline constexpr int kRowSpanBatch = 32;
inline constexpr int kRowSpanArray = kRowSpanBatch + 8;
void rowSpans(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi, bool simd);
void rowSpansScalar(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi);

// The pixel walk the scalar twins share: calls fn(x, y) for every pixel of the rect inside all
// three edges, row by row, left to right.
template <class Fn>
void forEachCoveredPixel(const TileEdges& e, Fn&& fn) {
  int y_lo, y_hi;
  if (!RowSpans(e).rows(y_lo, y_hi)) return;
  for (int y = y_lo; y <= y_hi; ++y) {
    const int ry = y - e.ty0;
    const int32_t r0 = e.e0[0] + e.dy[0] * ry, r1 = e.e0[1] + e.dy[1] * ry,
                  r2 = e.e0[2] + e.dy[2] * ry;
    for (int x = e.x0; x <= e.x1; ++x) {
      const int rx = x - e.tx0;
      if ((r0 + e.dx[0] * rx) >= 0 && (r1 + e.dx[1] * rx) >= 0 && (r2 + e.dx[2] * rx) >= 0)
        fn(x, y);
    }
  }
}

// The triangle's depth at pixel (x, y) of the rect, in the order the SIMD kernels use (their
// lanes add da * (rx + lane) to the row's value).
inline float triangleDepthAt(const TileEdges& e, int x, int y) {
  return (e.dc + e.db * float(y - e.ty0)) + e.da * float(x - e.tx0);
}

// Prepares `t` for the tile whose pixels are [tx0, tx1] x [ty0, ty1]; false when the triangle
// misses the tile entirely (an edge is negative at all four rect corners).
bool setupTileEdges(const SetupTriangle& t, int tx0, int ty0, int tx1, int ty1, TileEdges& out);
// The same in two steps, for passes that can cull the pair before its edges are set up: first
// the rect (the triangle's box within the tile), tile origin and depth (false: the box misses
// the tile), then the edges over that rect (false: an edge excludes the whole rect).
bool setupTileRect(const SetupTriangle& t, int tx0, int ty0, int tx1, int ty1, TileEdges& out);
bool setupRectEdges(const SetupTriangle& t, TileEdges& rect);

// Where a kernel reads and writes: row-major buffers of the full image.
// The depth target may be a tile's own copy: pixel (x, y) of the image is element
// (y - y0) * stride + (x - x0).
struct DepthTarget {
  float* depth;
  uint32_t* primitive;
  int stride;
  int x0 = 0, y0 = 0;
};
struct StencilTarget {
  const float* depth;
  int32_t* stencil;
  int stride;
  int x0 = 0, y0 = 0;  // as DepthTarget
  // The eye pass's primitive ids, laid out as `depth`; only read for polygons with owners.
  const uint32_t* primitive = nullptr;
};

// The visible triangles at whose pixels a polygon is not counted (ClipTriangles::owners).
struct StencilOwners {
  uint32_t first = 0xffffffffu, second = 0xffffffffu;
  bool any() const { return (first & second) != 0xffffffffu; }
};

enum class DepthRule : uint8_t {
  Closer,        // z-pass: count where the primitive is strictly in front of the stored depth
  NotCloser,     // z-fail: count where it is behind or at the stored depth
};

struct KernelCounts {
  uint64_t covered = 0;  // pixels inside the triangle
  uint64_t writes = 0;   // pixels written
};

// Eye pass: depth test (strictly closer wins, so the first drawn of equal depths stays) and
// write of depth and primitive id.
void depthKernel(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                 KernelCounts& counts, bool simd);

// Shadow volumes: for covered pixels with a surface (stored depth > 0), adds `contribution` to
// the stencil where the depth rule holds and the pixel's primitive is not one of `owners`.
// Every covered pixel reads the depth once (and its primitive, when there are owners).
void stencilKernel(const TileEdges& e, int32_t contribution, DepthRule rule,
                   const StencilTarget& target, KernelCounts& counts, bool simd,
                   StencilOwners owners = {});

// The scalar twins, also used by the scalar-only build.
void depthKernelScalar(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                       KernelCounts& counts);
void stencilKernelScalar(const TileEdges& e, int32_t contribution, DepthRule rule,
                         const StencilTarget& target, KernelCounts& counts,
                         StencilOwners owners = {});


}  // namespace penumbra
