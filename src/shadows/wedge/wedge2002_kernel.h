#pragma once
// The original penumbra wedge rasterization (2002 paper, section 4 pseudo-code, with the
// section 5 optimisations): per fragment of a front-facing wedge face, the entry point p_f on
// that face, the exit point p_b (the first back-facing plane the view ray leaves through),
// p_i = the closer of p_b and the depth-buffer point, and round(255 (s_i - s_f)) added to LI.
// Entry and exit through side planes count 0: the adjacent wedge's opposite crossing cancels
// it (section 5). Scalar only: it is the baseline the restructured algorithm is measured
// against, as in the 2004 paper.
#include "raster/tile_kernels.h"
#include "shadows/wedge/wedge_kernel.h"

namespace penumbra {

void wedge2002Kernel(const TileEdges& e, const ScreenWedge& wedge, int face, float li_scale,
                     const WedgeKernelTarget& target, WedgeKernelCounts& counts);

}  // namespace penumbra
