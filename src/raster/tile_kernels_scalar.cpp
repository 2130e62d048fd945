#include <algorithm>

#include "raster/fixed_point.h"
#include "raster/tile_kernels.h"

namespace penumbra {

bool setupTileRect(const SetupTriangle& t, int tx0, int ty0, int tx1, int ty1, TileEdges& out) {
  out.x0 = std::max(tx0, t.min_x);
  out.y0 = std::max(ty0, t.min_y);
  out.x1 = std::min(tx1, t.max_x);
  out.y1 = std::min(ty1, t.max_y);
  if (out.x0 > out.x1 || out.y0 > out.y1) return false;
  out.tx0 = tx0;
  out.ty0 = ty0;
  // Depth at the tile origin's pixel centre in double, then float steps from there: keeps the
  // float terms small so the float evaluation stays within a few ulps of the plane.
  out.dc = float(t.a * (tx0 + 0.5) + t.b * (ty0 + 0.5) + t.c);
  out.da = float(t.a);
  out.db = float(t.b);
  return true;
}

bool setupRectEdges(const SetupTriangle& t, TileEdges& out) {
  for (int i = 0; i < 3; ++i) {
    const int64_t A = t.A[i], B = t.B[i], C = t.C[i];
    auto edge = [&](int x, int y) { return A * pixelCentre(x) + B * pixelCentre(y) + C; };
    const int64_t c00 = edge(out.x0, out.y0), c10 = edge(out.x1, out.y0);
    const int64_t c01 = edge(out.x0, out.y1), c11 = edge(out.x1, out.y1);
    const int64_t lo = std::min({c00, c10, c01, c11}), hi = std::max({c00, c10, c01, c11});
    if (hi < 0) return false;
    if (lo >= 0) {  // the whole rect is inside this edge
      out.e0[i] = out.dx[i] = out.dy[i] = 0;
      continue;
    }
    // The edge crosses the rect, which lies in one bin tile: int32 holds it (fixed_point.h).
    out.e0[i] = int32_t(edge(out.tx0, out.ty0));
    out.dx[i] = int32_t(A * kSubpixelSteps);
    out.dy[i] = int32_t(B * kSubpixelSteps);
  }
  return true;
}

bool setupTileEdges(const SetupTriangle& t, int tx0, int ty0, int tx1, int ty1, TileEdges& out) {
  return setupTileRect(t, tx0, ty0, tx1, ty1, out) && setupRectEdges(t, out);
}

void depthKernelScalar(const TileEdges& e, uint32_t primitive, const DepthTarget& target,
                       KernelCounts& counts) {
  // Covered: inside all three edges (>= 0).
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    // Depth test: strictly closer (greater reversed-Z) wins, so the first drawn of equal
    // depths stays.
    const float d = triangleDepthAt(e, x, y);
    const size_t i = size_t(y - target.y0) * size_t(target.stride) + size_t(x - target.x0);
    if (d > target.depth[i]) {
      // Write depth and primitive id where it passes.
      target.depth[i] = d;
      target.primitive[i] = primitive;
      ++counts.writes;
    }
  });
}

void rowSpansScalar(const TileEdges& e, int y0, int count, int32_t* x_lo, int32_t* x_hi) {
  const RowSpans spans(e);
  for (int k = 0; k < count; ++k) {
    const int ry = y0 + k - e.ty0;
    const int32_t r[3] = {e.e0[0] + e.dy[0] * ry, e.e0[1] + e.dy[1] * ry, e.e0[2] + e.dy[2] * ry};
    int lo = 0, hi = -1;
    if (spans.span(r, lo, hi)) {
      x_lo[k] = lo;
      x_hi[k] = hi;
    } else {
      x_lo[k] = e.tx0 + 1;
      x_hi[k] = e.tx0;
    }
  }
}

void stencilKernelScalar(const TileEdges& e, int32_t contribution, DepthRule rule,
                         const StencilTarget& target, KernelCounts& counts,
                         StencilOwners owners) {
  const bool owned = owners.any();
  // Covered: inside all three edges (>= 0).
  forEachCoveredPixel(e, [&](int x, int y) {
    ++counts.covered;
    // Depth rule against the stored depth, only where there is a surface (stored depth > 0).
    const size_t i = size_t(y - target.y0) * size_t(target.stride) + size_t(x - target.x0);
    const float stored = target.depth[i];
    const float d = triangleDepthAt(e, x, y);
    const bool pass = rule == DepthRule::Closer ? d > stored : d <= stored;
    const bool own =
        owned && (target.primitive[i] == owners.first || target.primitive[i] == owners.second);
    if (stored > 0.0f && pass && !own) {
      // Add the contribution to the stencil where both hold.
      target.stencil[i] += contribution;
      ++counts.writes;
    }
  });
}

}  // namespace penumbra
