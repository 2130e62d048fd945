#include "shadows/hierarchical/tile_box_test.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "raster/fixed_point.h"

namespace penumbra {

namespace {

// The triangle's depths [lo, hi] (over some part of it) against the box's range [zmin, zmax],
// with the margin of the header: the float error of the kernels' depth evaluation (the bin
// tile's origin is within 4 bin tiles of reach) plus the plane's change over 1/8 pixel.
TileBoxClass decideDepths(const SetupTriangle& t, double lo, double hi, float zmin, float zmax) {
  const double reach = std::fabs(t.a) + std::fabs(t.b);
  const double error =
      8.0 * FLT_EPSILON * (std::max(std::fabs(lo), std::fabs(hi)) + 4.0 * kBinTileSize * reach) +
      reach / 8.0 + 1e-30;
  if (lo - error > double(zmax)) return TileBoxClass::Front;
  if (hi + error < double(zmin)) return TileBoxClass::Behind;
  return TileBoxClass::Crossing;
}

}  // namespace

TileBoxClass classifyDepthRange(const SetupTriangle& t, float zmin, float zmax) {
  return decideDepths(t, t.depth_min, t.depth_max, zmin, zmax);
}

TileBoxClass classifyTileBox(const SetupTriangle& t, int x0, int y0, int x1, int y1, float zmin,
                             float zmax) {
  // The tile's pixel-centre rectangle in 28.4 units, widened by one unit, clipped by the three
  // edge half-planes (A x + B y + C >= 0) in double: at most 3 + 4 corners remain.
  double px[8], py[8], qx[8], qy[8];
  const double lx = double(pixelCentre(x0) - 1), hx = double(pixelCentre(x1) + 1);
  const double ly = double(pixelCentre(y0) - 1), hy = double(pixelCentre(y1) + 1);
  auto decide = [&](double lo, double hi) { return decideDepths(t, lo, hi, zmin, zmax); };
  // Quick answers first, in the order most (triangle, tile) pairs of long shadow quads settle:
  // an edge with the whole rectangle outside it (at the corner where the edge function is
  // largest), then the plane's range over the whole rectangle, a superset of the triangle's part.
  for (int i = 0; i < 3; ++i) {
    const double A = t.A[i], B = t.B[i];
    if (A * (A > 0 ? hx : lx) + B * (B > 0 ? hy : ly) + double(t.C[i]) < 0.0)
      return TileBoxClass::Outside;
  }
  {
    const double z00 = t.a * (lx / kSubpixelSteps) + t.b * (ly / kSubpixelSteps) + t.c;
    const double across = t.a * ((hx - lx) / kSubpixelSteps);
    const double down = t.b * ((hy - ly) / kSubpixelSteps);
    const TileBoxClass whole = decide(z00 + std::min(across, 0.0) + std::min(down, 0.0),
                                      z00 + std::max(across, 0.0) + std::max(down, 0.0));
    if (whole != TileBoxClass::Crossing) return whole;
  }
  px[0] = lx, py[0] = ly, px[1] = hx, py[1] = ly, px[2] = hx, py[2] = hy, px[3] = lx, py[3] = hy;
  int n = 4;
  for (int i = 0; i < 3 && n > 0; ++i) {
    const double A = t.A[i], B = t.B[i], C = double(t.C[i]);
    double d[8];
    bool all_in = true;
    for (int k = 0; k < n; ++k) {
      d[k] = A * px[k] + B * py[k] + C;
      all_in &= d[k] >= 0.0;
    }
    if (all_in) continue;
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const int j = (k + 1) % n;
      if (d[k] >= 0.0) qx[m] = px[k], qy[m++] = py[k];
      if ((d[k] >= 0.0) != (d[j] >= 0.0)) {
        const double s = d[k] / (d[k] - d[j]);
        qx[m] = px[k] + (px[j] - px[k]) * s;
        qy[m++] = py[k] + (py[j] - py[k]) * s;
      }
    }
    n = m;
    std::copy_n(qx, n, px);
    std::copy_n(qy, n, py);
  }
  if (n == 0) return TileBoxClass::Outside;
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < n; ++k) {
    const double z = t.a * (px[k] / kSubpixelSteps) + t.b * (py[k] / kSubpixelSteps) + t.c;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  if (!(lo <= hi)) return TileBoxClass::Crossing;  // NaN plane: decide nothing
  return decide(lo, hi);
}

}  // namespace penumbra
