#pragma once
// The occlusion queries of the object-level culler (raster/occlusion_culler.h): an object's
// box projected to a screen rectangle and its nearest depth, tested against the occlusion
// buffer's tile z-min (Aila's thesis, section 3.1; docs/occlusion-culling.md), and the
// single-pixel query of a cached visible point. Depth is reversed-Z (core/view.h): larger is
// closer, 0 is background.
#include <cstdint>

#include "core/math.h"
#include "core/view.h"
#include "raster/depth_buffer.h"

namespace penumbra {

// Everything the rasterizer could draw of an object inside a box, on screen.
struct ScreenBox {
  enum class Kind : uint8_t {
    Outside,   // no pixel centre of the image can be covered: off screen or behind the eye
    Crossing,  // the box reaches the near plane (or the eye is inside it): never culled
    Inside,    // wholly in front of the near plane: the rect and depth below hold
  };
  Kind kind = Kind::Outside;
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // pixels, inclusive, clamped to the image
  // An upper bound of the depth the depth kernel stores for any of the box's triangles at any
  // pixel: the nearest corner's depth widened by kDepthSlack (see occlusion_query.cpp).
  double nearest = 0.0;
};

ScreenBox projectBox(const Bounds3& box, const View& view);

// True when every pixel of the rect already holds a surface strictly closer than the box's
// nearest depth: then none of the box's triangles can win a pixel of the final depth test,
// whatever is drawn later (depth only grows). Reads the z-min of the level whose tiles cut the
// rect into at most 2 x 2 (level 8 beyond) and, where a tile does not decide, of its children
// over the rect, down to 4 x 4 pixels or four levels. Counts the tiles read.
bool boxHidden(const ScreenBox& box, const DepthBuffer& occlusion, uint64_t& tiles_read);

// The single-pixel query of visible point tracking (thesis, section 3.1): true when the point
// is in front of the near plane, on screen and not behind the depth stored at its pixel, so the
// object holding it is taken as visible without the box query.
bool pointVisible(const vec3& point, const View& view, const DepthBuffer& occlusion);

}  // namespace penumbra
