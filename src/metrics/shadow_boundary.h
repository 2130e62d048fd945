#pragma once
// Agreement of a hard-shadow visibility image with the oracle's, allowing for ties: a pixel
// whose centre lies on a shadow boundary can legitimately fall on either side, because the
// two methods round geometry differently (28.4 snapping vs the ray tracer's float
// intersection). A differing pixel counts as a tie when the oracle itself changes value
// within its 8-neighbourhood; a differing pixel in a uniform oracle region is an error.
#include <cstdint>

#include "core/image.h"

namespace penumbra {

struct BoundaryAgreement {
  uint64_t covered = 0;       // pixels compared (mask true)
  uint64_t differing = 0;     // |a - b| > 0.5
  uint64_t off_boundary = 0;  // differing pixels that are not ties
  double differingFraction() const { return covered ? double(differing) / double(covered) : 0.0; }
};

// `mask`: pixels to compare (e.g. the eye pass's covered pixels); empty = all.
BoundaryAgreement compareHardShadows(const Image<float>& technique, const Image<float>& oracle,
                                     const Image<uint8_t>& mask);

}  // namespace penumbra
