#pragma once
// The points on a light that the Heckbert-Herf average renders hard shadows from.
#include <vector>

#include "core/math.h"
#include "scene/light.h"

namespace penumbra {

// n stratified points, uniform in the light's area, jittered by `seed` (fixedSamples): on a
// disk or rectangle light the light itself; on a sphere the disk through its centre facing
// `toward` (the scene's centre), which is what every receiver near that direction sees of it.
// A point `toward` at the centre itself takes the disk facing down (-y).
std::vector<vec3> heckbertHerfPoints(const Light& light, int n, uint64_t seed,
                                     const vec3& toward);

}  // namespace penumbra
