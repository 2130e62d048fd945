#pragma once
// The per-point half of PCSS (Fernando 2005), on a LightDepthMaps: the three steps for one
// visible point, in the map's texels.
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "shadows/shadowmap/light_depth_maps.h"

namespace penumbra {

struct PcssSettings {
  double radius = 0;           // the sphere light's radius, world units
  double constant_bias = 1.0;  // texels
  double slope_bias = 1.0;     // texels per texel of offset, x the receiver's slope
  int blocker_samples = 16;
  int filter_samples = 32;
};

// Light visibility of point p, which lands at `m` in `maps`, on a surface of slope `slope`
// (receiverSlope); `rotation` in [0, 1) turns the sample spirals (a turn per unit).
// `nearest_occluder` is nearestOccluders(maps)[m.face]. Adds the depth-map reads it makes to
// `reads`.
float pcssVisibility(const LightDepthMaps& maps, const MapPoint& m, double slope,
                     double rotation, const PcssSettings& settings, uint64_t& reads,
                     double nearest_occluder);

// The nearest occluder distance of each face of `maps` (+infinity for an empty face): no
// blocker lies closer to the light, which bounds the blocker search.
std::vector<double> nearestOccluders(const LightDepthMaps& maps);

// A turn in [0, 1) for pixel (x, y): an integer hash, so that it is the same for any thread
// count and for SIMD or scalar runs.
double pixelRotation(int x, int y);

}  // namespace penumbra
