#pragma once
// The masks' own counter: pixels where the 8-bit mask could not hold the volume count.
#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kMaskSaturatedPixels{
    "mask_saturated_pixels",
    "pixels where a volume's halvings went below 1/255 (mask_values.h): the mask may differ "
    "from the stencil there"};

}  // namespace penumbra
