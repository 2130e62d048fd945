#pragma once
// Options of percentage-closer soft shadows (`pcss`, Fernando 2005). For typed access:
//   config.options<penumbra::PcssOptions>().filter_samples = 64;
#include <penumbra/shadows/shadow_map_options.h>

namespace penumbra {

struct PcssOptions {
  // The shadow map's own options, as for `shadow-map` (cube or fitted spot; no spotlights).
  int resolution = 1024;
  ShadowMapProjection projection = ShadowMapProjection::Auto;
  // Bias in texels at the receiver's distance: constant, plus slope x tan(normal, light
  // direction) x each lookup's distance from the projected point in texels (plus half a texel),
  // the tangent capped at 10: a planar receiver's own depth changes by that much there.
  double constant_bias = 1.0;
  double slope_bias = 1.0;
  // Lookups of the blocker search, over the disk of the map through which the light's sphere
  // sees the receiver, and of the filter, over the disk the penumbra estimate gives. Each is
  // a fixed spiral of points, turned by a per-pixel angle (a hash of the pixel), so the error
  // is noise rather than bands.
  int blocker_samples = 16;
  int filter_samples = 32;
};

}  // namespace penumbra
