#pragma once
// Options of the standard shadow map (`shadow-map`, Williams 1978). For typed access:
//   config.options<penumbra::ShadowMapOptions>().resolution = 2048;
namespace penumbra {

struct ShadowMapOptions {
  // Texels along each side of each of the six cube faces around the light centre.
  int resolution = 1024;
  // Percentage-closer filtering: an N x N kernel of depth lookups around the projected point,
  // visibility = the fraction that is lit. 1 = the plain shadow map (0 or 1 per pixel). Odd.
  int pcf_kernel = 3;
  // Depth bias subtracted from the receiver before it is compared with an occluder, both in
  // units of the world size of one texel at the receiver's distance: constant_bias texels, plus
  // slope_bias x tan(angle between the surface normal and the direction to the light) x the
  // kernel's reach ((N + 1) / 2 texels), the tangent capped at 10.
  double constant_bias = 1.0;
  double slope_bias = 1.0;
};

}  // namespace penumbra
