#pragma once
// shadeFrame (render/shading.h) into a caller-owned image, for loops that render frame after
// frame (render/frame.h, renderFrame with a FrameResult to reuse): `out` is resized only when
// the view's size changed and every pixel is written, background included, so no frame pays
// for allocating, clearing and page-faulting a new full-size colour image. `simd` false runs
// the scalar twin of the shading kernel (render/shading_kernel.h); both give identical colours.
// `channels[i]`, when given and not null, is light i's visibility per colour channel (a textured
// light, shadows/technique.h): the light is shaded as three lights, one per channel, each with
// its channel's radiance and visibility (shading is linear in both). `triangles`, when given,
// is the scene's table of triangle records kept from frame to frame (a record depends on the
// triangle alone; FrameRenderer keeps one): the frame then builds only the records no earlier
// frame needed. Without it, the frame builds its own.
#include <vector>

#include "core/image.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/scene.h"
#include "shadows/technique.h"

namespace penumbra {

class ShadingTriangleTable;

void shadeFrameInto(const Scene& scene, const View& view, const EyeBuffers& eye,
                    const std::vector<const Image<float>*>& visibility, Image<vec3>& out,
                    bool simd = true,
                    const std::vector<const ChannelVisibility*>& channels = {},
                    ShadingTriangleTable* triangles = nullptr);

}  // namespace penumbra
