#pragma once
// Tile occlusion culling of the penumbra (2004 paper, section 4).
#include "raster/tile_kernels.h"
#include "shadows/technique.h"
#include "shadows/wedge/wedge_screen.h"

namespace penumbra {

// True when no depth-buffer point of the rect can lie inside the wedge, given the tile's stored
// depth range [zmin, zmax] (reversed-Z). ZMax: the wedge is entirely behind the tile's farthest
// point (the test common hardware has). Full: also the quick z-range reject (wedge entirely in
// front of the nearest point), then the screen-space box of the tile against each wedge plane,
// testing only the box corner that maximises the plane (the p-vertex, Figure 7). Conservative:
// the margin covers the float error of the kernels' plane evaluation.
bool penumbraCulled(CullMode mode, const ScreenWedge& wedge, const TileEdges& rect, float zmin,
                    float zmax);

}  // namespace penumbra
