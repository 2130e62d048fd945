#pragma once
// Tile occlusion culling of the penumbra (2004 paper, section 4).
#include <string>

#include "raster/tile_kernels.h"
#include "shadows/wedge/wedge_screen.h"
#include "shadows/wedge_options.h"

namespace penumbra {

// A wedge's culling planes with their error margins, set up once per wedge and frame.
struct WedgeCullPlanes {
  const ScreenWedge* wedge = nullptr;
  // Per plane (front, back, left, right): a plane value below -margin anywhere in the image
  // proves the kernels' float evaluation is negative there too.
  double margin[4];
};

// `width` x `height`: the image, whose culling tiles may reach past it up to the largest tile.
WedgeCullPlanes wedgeCullPlanes(const ScreenWedge& wedge, int width, int height);

// True when no depth-buffer point of the rect (a culling tile, or the part of one a triangle's
// box covers) can lie inside the wedge, given the tile's stored depth range [zmin, zmax]
// (reversed-Z). ZMax: the wedge is entirely behind the tile's farthest point (the test common
// hardware has). Full: also the quick z-range reject (wedge entirely in front of the nearest
// point), then the rect's screen-space box against each wedge plane, testing only the box
// corner that maximises the plane (the p-vertex, Figure 7). Conservative: the margins cover the float error of the
// kernels' plane evaluation.
bool penumbraCulled(CullMode mode, const WedgeCullPlanes& planes, const TileEdges& rect,
                    float zmin, float zmax);

}  // namespace penumbra
