#pragma once
// Per-frame and per-pixel inputs of PCSS's kernel (pcss_kernel.h): the bound on the blocker
// search and the pixel's turn of the sample spirals.
#include <cstdint>
#include <vector>

#include "shadows/stages/light_depth_maps/light_depth_maps.h"

namespace penumbra {

// The nearest occluder distance of each face of `maps` (+infinity for an empty face): no
// blocker lies closer to the light, which bounds the blocker search.
std::vector<double> nearestOccluders(const LightDepthMaps& maps);

// A turn in [0, 1) for pixel (x, y): an integer hash, so that it is the same for any thread
// count and for SIMD or scalar runs.
double pixelRotation(int x, int y);

// The share of a sphere light of `radius` whose centre lies `height` above the receiver's plane
// that is above that plane (PcssOptions::horizon): the light's disk, as the receiver sees it,
// cut by the plane's horizon line at height / radius of its radius from the centre (small
// angles: the light is far compared with its radius). 1 for a point light.
double aboveHorizon(double height, double radius);

}  // namespace penumbra
