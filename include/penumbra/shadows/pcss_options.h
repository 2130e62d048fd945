#pragma once
// Options of percentage-closer soft shadows (`pcss`, Fernando 2005). For typed access:
//   config.options<penumbra::PcssOptions>().filter_samples = 64;
#include <penumbra/shadows/shadow_map_options.h>

namespace penumbra {

// Which depth-map samples count as occluders, in the blocker search and in the filter.
enum class PcssOccluderTest {
  // Fernando 2005: any sample in front of the receiver less the constant and slope biases.
  Depth,
  // Only a sample whose surface point lies more than constant_bias texels above the plane of
  // the receiver's triangle (through the looked-up point): the receiver-plane test, exact in
  // world space (ReceiverPlane in src/shadows/stages/light_depth_maps/shadow_map_lookup.h).
  // A planar receiver never finds itself, at any angle, so neither the blocker average nor
  // the filter sees it; the slope bias is not used.
  Plane,
};

struct PcssOptions {
  // The shadow map's own options, as for `shadow-map` (cube or fitted spot; no spotlights).
  int resolution = 1024;
  ShadowMapProjection projection = ShadowMapProjection::Auto;
  // Bias in texels at the receiver's distance: constant, plus slope x tan(normal, light
  // direction) x each lookup's distance from the projected point in texels (plus half a texel),
  // the tangent capped at 10: a planar receiver's own depth changes by slope 1 x that much
  // there. 1.5 rather than 1 covers the rough surfaces whose neighbouring facets rise faster
  // than the receiver's own (chosen on `fractal` and the terrain: docs/shadow-maps.md, "Bias").
  double constant_bias = 1.0;
  double slope_bias = 1.5;
  // Normal-offset sampling (shadow_map_lookup.h): the point is looked up this many texels (at its
  // distance) off its surface, along its normal.
  double normal_offset = 0.0;
  PcssOccluderTest occluder_test = PcssOccluderTest::Depth;
  // Lookups of the blocker search, over the disk of the map through which the light's sphere
  // sees the receiver, and of the filter, over the disk the penumbra estimate gives. Each is
  // a fixed spiral of points, turned by a per-pixel angle (a hash of the pixel), so the error
  // is noise rather than bands.
  // The receiver's own horizon: a point whose plane cuts the light's disk sees only the part
  // above it (the oracle blocks rays that start into the surface), so its visibility is scaled
  // by that share. Fernando 2005 has no such term: lit grazing surfaces come out fully lit.
  bool horizon = true;
  int blocker_samples = 16;
  int filter_samples = 32;
};

}  // namespace penumbra
