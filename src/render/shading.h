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
// background colour. Linear RGB out. `visibility[i]` belongs to scene.lights[i]; a null entry
// means that light is unshadowed (visibility 1 everywhere).
//
// The shading normal interpolates the triangle's corner normals at the visible point and faces
// the eye: open meshes are drawn two-sided, so their back faces are lit as front faces.
// Lights have no distance falloff (scene/light.h). Throws penumbra::Error when the buffers do
// not match the view or the scene (unfinalized scene, wrong number of visibility buffers).
Image<vec3> shadeFrame(const Scene& scene, const View& view, const EyeBuffers& eye,
                       const std::vector<const Image<float>*>& visibility);

}  // namespace penumbra
