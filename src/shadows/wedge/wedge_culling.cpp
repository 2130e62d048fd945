#include "shadows/wedge/wedge_culling.h"

#include <cfloat>
#include <cmath>

namespace penumbra {
namespace {

// Largest value of the plane over the box [x0, x1] x [y0, y1] x [z0, z1] (pixel centres), minus
// a bound on the float error of evaluating it at any of those points.
bool boxOutside(const ScreenPlane& p, double x0, double x1, double y0, double y1, double z0,
                double z1) {
  const double x = p.a >= 0 ? x1 : x0, y = p.b >= 0 ? y1 : y0, z = p.c >= 0 ? z1 : z0;
  const double top = double(p.a) * x + double(p.b) * y + double(p.c) * z + double(p.d);
  const double scale = std::fabs(double(p.a)) * std::max(std::fabs(x0), std::fabs(x1)) +
                       std::fabs(double(p.b)) * std::max(std::fabs(y0), std::fabs(y1)) +
                       std::fabs(double(p.c)) + std::fabs(double(p.d));
  return top < -8.0 * FLT_EPSILON * scale;
}

}  // namespace

bool penumbraCulled(CullMode mode, const ScreenWedge& w, const TileEdges& r, float zmin,
                    float zmax) {
  if (mode == CullMode::None) return false;
  if (w.z_near < zmin) return true;  // the whole wedge lies behind every stored point
  if (mode == CullMode::ZMax) return false;
  if (zmax <= 0.0f) return true;    // only background
  if (w.z_far > zmax) return true;  // the whole wedge lies in front of every stored point
  const double x0 = r.x0 + 0.5, x1 = r.x1 + 0.5, y0 = r.y0 + 0.5, y1 = r.y1 + 0.5;
  for (const ScreenPlane* p : {&w.front, &w.back, &w.left, &w.right})
    if (boxOutside(*p, x0, x1, y0, y1, zmin, zmax)) return true;
  return false;
}

}  // namespace penumbra
