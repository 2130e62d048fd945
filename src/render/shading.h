#pragma once
#include <vector>

#include "core/image.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"
#include "shadows/technique.h"

namespace penumbra {

// Deferred shading in the papers' order: for each light, (Lambert diffuse + Blinn-Phong
// specular) x visibility, then ambient x albedo added; background pixels get the scene's
// background colour. Linear RGB out. `visibility[i]` belongs to scene.lights[i].
Image<vec3> shadeFrame(const Scene& scene, const View& view, const EyeBuffers& eye,
                       const std::vector<const Image<float>*>& visibility);

}  // namespace penumbra
