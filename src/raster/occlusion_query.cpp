#include "raster/occlusion_query.h"

#include <algorithm>
#include <cmath>

namespace penumbra {
namespace {

// The depth kernel evaluates each triangle's plane in float from the tile's corner, and its
// coverage uses vertices snapped to 1/16 pixel while its plane comes from the unsnapped ones:
// a pixel centre it covers may lie a fraction of a pixel outside the triangle, where the plane
// is extrapolated. A relative slack of 1e-3 covers the float error by orders of magnitude and
// the extrapolation for every triangle whose depth changes by less than a thousandth of its
// depth over 1/16 pixel (anything but a sliver seen almost exactly edge-on); the rect is widened
// by two pixels for the snapping.
constexpr double kDepthSlack = 1e-3;
constexpr int kRectSlack = 2;

}  // namespace

ScreenBox projectBox(const Bounds3& box, const View& view) {
  ScreenBox out;
  if (box.empty()) return out;
  double min_x = HUGE_VAL, min_y = HUGE_VAL, max_x = -HUGE_VAL, max_y = -HUGE_VAL;
  double min_w = HUGE_VAL;
  const double near = double(view.near_plane);
  // Frustum culling in homogeneous clip space, valid whatever the sign of w: the visible region
  // is -w <= x <= w, -w <= y <= w, w >= near, and a box whose eight corners all lie beyond one
  // of these planes (by the rect's slack of two pixels and a relative hair) lies beyond it
  // whole, behind the eye included. Bit b of `beyond` stays set while every corner is beyond
  // plane b.
  const double slack_x = 2.0 * (kRectSlack + 1) / view.width + 1e-3;
  const double slack_y = 2.0 * (kRectSlack + 1) / view.height + 1e-3;
  unsigned beyond = 31;
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    const vec4 c = view.toClip(vec4(p, 1.0f));
    const double w = double(c.w), x = double(c.x), y = double(c.y), aw = std::fabs(w);
    unsigned planes = 0;
    if (x - w > slack_x * aw) planes |= 1;
    if (-x - w > slack_x * aw) planes |= 2;
    if (y - w > slack_y * aw) planes |= 4;
    if (-y - w > slack_y * aw) planes |= 8;
    if (near - w > 1e-3 * near) planes |= 16;
    beyond &= planes;
    min_w = std::min(min_w, w);
    if (!(w > 0.0)) continue;
    const double sx = (double(c.x) / w * 0.5 + 0.5) * view.width;
    const double sy = (0.5 - double(c.y) / w * 0.5) * view.height;
    min_x = std::min(min_x, sx);
    max_x = std::max(max_x, sx);
    min_y = std::min(min_y, sy);
    max_y = std::max(max_y, sy);
  }
  if (beyond != 0) return out;
  // w is affine over the box, so its corners hold its minimum. Within a hair of the near plane
  // the near-plane clipping of the rasterizer may cut the object: not tested, drawn.
  if (!(min_w > near * (1.0 + 1e-3) + 1e-6)) {
    out.kind = ScreenBox::Kind::Crossing;
    out.x0 = 0;
    out.y0 = 0;
    out.x1 = view.width - 1;
    out.y1 = view.height - 1;
    return out;
  }
  // Pixel x's centre is x + 0.5: the covered centres lie in [min_x - 0.5, max_x - 0.5].
  const double x0 = std::floor(min_x - 0.5) - kRectSlack, x1 = std::ceil(max_x - 0.5) + kRectSlack;
  const double y0 = std::floor(min_y - 0.5) - kRectSlack, y1 = std::ceil(max_y - 0.5) + kRectSlack;
  if (x1 < 0.0 || y1 < 0.0 || x0 > view.width - 1.0 || y0 > view.height - 1.0) return out;
  out.kind = ScreenBox::Kind::Inside;
  out.x0 = int(std::max(0.0, x0));
  out.y0 = int(std::max(0.0, y0));
  out.x1 = int(std::min(view.width - 1.0, x1));
  out.y1 = int(std::min(view.height - 1.0, y1));
  // depth = near / w (core/view.h): largest at the smallest w.
  out.nearest = near / min_w * (1.0 + kDepthSlack);
  return out;
}

namespace {

// Tile (tx, ty) of `level` and, where its z-min does not decide, its children down to
// `finest`, over the rect only: true when every pixel of the rect in the tile is covered by a
// surface strictly closer than `nearest` (a tie could go to the object). The coarse z-min is the
// farthest of its pixels, so a tile holding some sky (0) or a far surface beside the occluder
// fails as a whole, while its children beside the sky may not (the refinement of a depth
// pyramid's test, Greene and Kass's hierarchical z-buffer that the thesis's section 2.1 cites).
bool tileHidden(const ScreenBox& box, const DepthBuffer& occlusion, int level, int tx, int ty,
                int finest, uint64_t& tiles_read) {
  ++tiles_read;
  if (double(occlusion.tiles[level].zmin.at(tx, ty)) > box.nearest) return true;
  if (level <= finest) return false;
  const int child = level - 1;
  for (int cy = std::max(2 * ty, box.y0 >> child); cy <= std::min(2 * ty + 1, box.y1 >> child);
       ++cy)
    for (int cx = std::max(2 * tx, box.x0 >> child); cx <= std::min(2 * tx + 1, box.x1 >> child);
         ++cx)
      if (!tileHidden(box, occlusion, child, cx, cy, finest, tiles_read)) return false;
  return true;
}

}  // namespace

bool boxHidden(const ScreenBox& box, const DepthBuffer& occlusion, uint64_t& tiles_read) {
  if (box.kind != ScreenBox::Kind::Inside) return false;
  int level = kMinTileLevel;
  while (level < kMaxTileLevel &&
         ((box.x1 >> level) - (box.x0 >> level) >= 2 || (box.y1 >> level) - (box.y0 >> level) >= 2))
    ++level;
  // Down to tiles of 4x4 pixels, at most four levels below the first: the reads stay a small
  // fraction of the rect's pixels.
  const int finest = std::max(2, level - 4);
  for (int ty = box.y0 >> level; ty <= box.y1 >> level; ++ty)
    for (int tx = box.x0 >> level; tx <= box.x1 >> level; ++tx)
      if (!tileHidden(box, occlusion, level, tx, ty, finest, tiles_read)) return false;
  return true;
}

bool pointVisible(const vec3& point, const View& view, const DepthBuffer& occlusion) {
  const vec4 c = view.toClip(vec4(point, 1.0f));
  if (!(c.w > view.near_plane)) return false;
  const double sx = (double(c.x) / c.w * 0.5 + 0.5) * view.width;
  const double sy = (0.5 - double(c.y) / c.w * 0.5) * view.height;
  if (!(sx >= 0.0 && sy >= 0.0 && sx < view.width && sy < view.height)) return false;
  const double depth = double(view.near_plane) / double(c.w);
  // A point on the surface it was seen on a frame ago, recovered from that frame's depth: a
  // relative hair of slack, so it is not hidden behind its own surface.
  return depth * (1.0 + 1e-4) >= double(occlusion.depth.at(int(sx), int(sy)));
}

}  // namespace penumbra
