#include "shadows/wedge/wedge_culling.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/error.h"
#include "raster/depth_buffer.h"

namespace penumbra {

std::string cullModeName(CullMode mode) {
  switch (mode) {
    case CullMode::None: return "none";
    case CullMode::ZMax: return "zmax";
    case CullMode::Full: return "full";
  }
  return "unknown";
}

CullMode parseCullMode(const std::string& name) {
  for (CullMode m : {CullMode::None, CullMode::ZMax, CullMode::Full})
    if (cullModeName(m) == name) return m;
  throw Error(fmt::format("unknown culling mode '{}' (known: none, zmax, full)", name));
}
namespace {

// Largest value of the plane over the box [x0, x1] x [y0, y1] x [z0, z1] (pixel centres): at
// the corner the plane's gradient points to.
double planeMax(const ScreenPlane& p, double x0, double x1, double y0, double y1, double z0,
                double z1) {
  const double x = p.a >= 0 ? x1 : x0, y = p.b >= 0 ? y1 : y0, z = p.c >= 0 ? z1 : z0;
  return double(p.a) * x + double(p.b) * y + double(p.c) * z + double(p.d);
}

}  // namespace

WedgeCullPlanes wedgeCullPlanes(const ScreenWedge& wedge, int width, int height) {
  WedgeCullPlanes c;
  c.wedge = &wedge;
  // Pixel centres of any culling tile: up to the image rounded up to the largest tile. The
  // kernels evaluate ((a sx + b sy) + c z) + d in float with z in [0, 1]: four roundings, each
  // within FLT_EPSILON of the sum of the terms' magnitudes; 8 FLT_EPSILON leaves room.
  const int tile = 1 << kMaxTileLevel;
  const double x_max = double((width + tile - 1) / tile * tile) + 0.5;
  const double y_max = double((height + tile - 1) / tile * tile) + 0.5;
  const ScreenPlane* planes[4] = {&wedge.front, &wedge.back, &wedge.left, &wedge.right};
  for (int i = 0; i < 4; ++i) {
    const ScreenPlane& p = *planes[i];
    c.margin[i] = 8.0 * FLT_EPSILON *
                  (std::fabs(double(p.a)) * x_max + std::fabs(double(p.b)) * y_max +
                   std::fabs(double(p.c)) + std::fabs(double(p.d)));
  }
  return c;
}

bool penumbraCulled(CullMode mode, const WedgeCullPlanes& planes, const TileEdges& r,
                    float zmin, float zmax) {
  if (mode == CullMode::None) return false;
  const ScreenWedge& w = *planes.wedge;
  if (w.z_near < zmin) return true;  // the whole wedge lies behind every stored point
  if (mode == CullMode::ZMax) return false;
  if (zmax <= 0.0f) return true;    // only background
  if (w.z_far > zmax) return true;  // the whole wedge lies in front of every stored point
  const double bx0 = r.x0 + 0.5, bx1 = r.x1 + 0.5, by0 = r.y0 + 0.5, by1 = r.y1 + 0.5;
  const ScreenPlane* p[4] = {&w.front, &w.back, &w.left, &w.right};
  for (int i = 0; i < 4; ++i)
    if (planeMax(*p[i], bx0, bx1, by0, by1, zmin, zmax) < -planes.margin[i]) return true;
  return false;
}

}  // namespace penumbra
