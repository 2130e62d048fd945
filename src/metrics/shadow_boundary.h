#pragma once
// Agreement of a hard-shadow visibility image with the oracle's, allowing for ties: a pixel
// whose sample lies on a shadow boundary can legitimately fall on either side, because the two
// methods round geometry differently (28.4 snapping and float depth vs the ray tracer's
// intersection). A differing pixel is a tie when, within its 8-neighbourhood,
//  - the oracle changes value (the sample is on the oracle's shadow boundary), or
//  - the technique changes value (it is on the technique's boundary), or
//  - the visible surface ends (background, or a depth jump of more than 2 %): shadow volumes
//    start at the casters' edges, so along a caster's outline the sample is on the volume's
//    boundary, and snapping decides which side it falls on.
// A differing pixel in a region where both images and the surface are uniform is an error.
#include <cstdint>

#include "core/image.h"

namespace penumbra {

struct BoundaryAgreement {
  uint64_t covered = 0;       // pixels compared (depth > 0)
  uint64_t differing = 0;     // on different sides of 0.5
  uint64_t off_boundary = 0;  // differing pixels that are not ties
  double differingFraction() const { return covered ? double(differing) / double(covered) : 0.0; }
};

// `depth`: the eye pass's reversed-Z depth (0 = background, not compared).
BoundaryAgreement compareHardShadows(const Image<float>& technique, const Image<float>& oracle,
                                     const Image<float>& depth);

}  // namespace penumbra
