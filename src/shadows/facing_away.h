#pragma once
#include "core/image.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"

namespace penumbra {

// A visible point whose own triangle faces away from the whole light receives none of it: the
// surface shadows itself. Sets those pixels' visibility to 0 ("faces away": the light sphere
// lies entirely on the far side of the triangle's plane from the side the eye sees; for a point
// light, the centre lies strictly on that side). Shadow volumes only get this right up to
// rounding where a silhouette quad grazes the surface along the terminator; the oracle decides
// it exactly, from the triangle's vertices, and so does this.
void shadowFacingAway(const Scene& scene, const Light& light, const View& view,
                      const EyeBuffers& eye, Image<float>& visibility);

}  // namespace penumbra
