#pragma once
// Section 4.5's magnification: the low-resolution mask, copied into a texture, is stretched over
// the window with bilinear filtering.
#include "core/image.h"

namespace penumbra {

// `low` stretched to width x height over the same screen rectangle, bilinear, edges clamped:
// pixel (x, y)'s centre falls at low-resolution coordinates ((x + 0.5) low.width / width - 0.5,
// likewise in y), between the centres of the four texels around it. Rows in parallel.
Image<float> magnifyBilinear(const Image<float>& low, int width, int height);

}  // namespace penumbra
