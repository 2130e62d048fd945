#pragma once
// The original penumbra wedge rasterization (2002 paper, section 4 pseudo-code, with the
// section 5 optimisations): per fragment of a front-facing wedge face, the entry intensity s_f
// (1 on the front plane, 0 on the back and side planes) where the face passes the depth test,
// p_i = the closer of the depth-buffer point p and the exit p_b, and round(255 (s_i - s_f))
// added to LI in one write. Exits through side and back planes count 0 (section 5: the
// neighbour's entry cancels a side crossing); exits through the front plane are counted by the
// back-facing front faces themselves (wedge_technique.cpp). The decisions are those of the
// restructured kernel (wedge_kernel.h), so the two differ only by rounding 255 (s - 1) at once
// instead of 255 s and -255 apart: at most one LI unit per wedge entered through its front
// plane whose inside holds p. Scalar only: it is the baseline, as in the 2004 paper.
#include "raster/tile_kernels.h"
#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {

void wedge2002Kernel(const TileEdges& e, const ScreenWedge& wedge, int face, float li_scale,
                     const WedgeKernelTarget& target, WedgeKernelCounts& counts);

}  // namespace penumbra
