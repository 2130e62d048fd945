#pragma once
// Stencil-limited shadow-map lookups (Arvo & Aila 2003, the thesis's publication P4; Aila 2005
// thesis, section 4.2): the spot's frustum is a closed volume, the light's own "shadow volume"
// with the inside lit, rasterized into a stencil over the eye's depth buffer the way hard
// shadow volumes are (rasterizeStencil, z-fail: the eye may be inside it), so that lookups and
// lighting run only for pixels whose visible point lies inside.
#include <cstdint>

#include "core/image.h"
#include "core/stats.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "shadows/stages/light_depth_maps/light_frustum.h"

namespace penumbra {

// The spot frustum grows by this fraction of its half angle's tangent in the stencil, so that
// the stencil holds every point a lookup would find inside the frustum despite rounding: the
// lookup's own projection decides the frustum's edge, the stencil only skips points well
// outside (the limited image equals the unlimited one).
inline constexpr double kStencilFrustumMargin = 1e-3;

// Per pixel, the number of times the visible point lies inside the frustum of `face` from the
// light centre (1 inside, 0 outside; the background counts 0). Adds the pass "light frustum"
// and the stencil pass's counters to `stats`.
Image<int32_t> lightFrustumStencil(const Light& light, const LightFace& face, const View& view,
                                   const EyeBuffers& eye, Stats& stats, bool simd);

}  // namespace penumbra
