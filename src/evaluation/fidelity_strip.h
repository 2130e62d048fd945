#pragma once
// The fidelity page's pictures: technique | oracle | error heat map side by side, shrunk for
// the page (metrics/heatmap.h colours, core/image_io.h writes).
#include <cstdint>
#include <string>

#include <penumbra/core/image.h>
#include <penumbra/core/math.h>

namespace penumbra {

// The three panels with a 2-pixel white gap between them, each shrunk by `shrink` (1, 2 or 4)
// with a box filter over 8-bit values. The heat map draws |technique - oracle| =
// `heat_scale` (or more) brightest. Throws penumbra::Error when the sizes differ.
Image<glm::u8vec3> fidelityStrip(const Image<float>& technique, const Image<float>& oracle,
                                 float heat_scale, int shrink);
void writeFidelityStrip(const std::string& path, const Image<float>& technique,
                        const Image<float>& oracle, float heat_scale, int shrink);

// Box-filter shrink of an 8-bit RGB image by an integer factor; edge pixels average what is
// there. Throws for a factor below 1.
Image<glm::u8vec3> shrinkImage(const Image<glm::u8vec3>& image, int factor);

}  // namespace penumbra
