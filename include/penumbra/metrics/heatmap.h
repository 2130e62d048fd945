#pragma once
// Error and visibility images for people, as 8-bit RGB ready to write (core/image_io.h).
#include <cstdint>

#include <penumbra/core/image.h>
#include <penumbra/core/math.h>

namespace penumbra {

// A perceptual, monotonically brightening colour map (matplotlib's 'inferno', approximated by
// nine control points with linear interpolation) for t in [0, 1], clamped. t = 0 is exactly
// black so that "no error" reads as black; NaN maps to the t = 1 colour.
glm::u8vec3 errorColor(float t);

// Colours the per-pixel error (as in metrics/image_compare.h) divided by `max_error_for_scale`
// (> 0): black where the images agree, brightest at or above the scale. Non-finite errors get
// the brightest colour. Throws penumbra::Error when the sizes differ.
Image<glm::u8vec3> diffHeatmap(const Image<float>& a, const Image<float>& b,
                               float max_error_for_scale);
Image<glm::u8vec3> diffHeatmap(const Image<vec3>& a, const Image<vec3>& b,
                               float max_error_for_scale);

// A visibility buffer as gray: v in [0, 1] -> round(255 v) in every channel (clamped, no
// transfer curve, like core/image_io.h's gray PNGs).
Image<glm::u8vec3> visibilityToImage(const Image<float>& visibility);

}  // namespace penumbra
