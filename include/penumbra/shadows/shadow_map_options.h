#pragma once
// Options of the standard shadow map (`shadow-map`, Williams 1978). For typed access:
//   config.options<penumbra::ShadowMapOptions>().resolution = 2048;
namespace penumbra {

// How the light's depth is laid out (Aila 2005 thesis, section 2.3: one frustum covers a
// limited field of view; a light inside or near the view needs several).
enum class ShadowMapProjection {
  Auto,  // spot when the light is outside the box of the view's visible points and a frustum
         // of at most 90 degrees holds that box; cube otherwise
  Cube,  // six 90-degree faces around the light centre: any light position
  Spot,  // one square frustum from the light centre (spot_fov says which)
};

struct ShadowMapOptions {
  // Texels along each side of each face (six for a cube, one for a spot).
  int resolution = 1024;
  // Percentage-closer filtering: an N x N kernel of depth lookups around the projected point,
  // visibility = the fraction that is lit. 1 = the plain shadow map (0 or 1 per pixel). Odd.
  int pcf_kernel = 3;
  // Depth bias subtracted from the receiver before it is compared with an occluder, both in
  // units of the world size of one texel at the receiver's distance: constant_bias texels, plus
  // slope_bias x tan(angle between the surface normal and the direction to the light) x the
  // kernel's reach ((N + 1) / 2 texels), the tangent capped at 10 (the slope-scaled bias, an
  // option: 0 by default).
  // Normal-offset sampling: the point is looked up normal_offset x the kernel's reach texels
  // (at its distance) off its surface, along the visible triangle's normal. At 1 a planar
  // receiver cannot shadow itself within the kernel at any angle
  // (src/shadows/stages/light_depth_maps/shadow_map_lookup.h); below 1 the ring bias covers the
  // off-centre taps of a plane up to tan(angle) = ring_bias, so the default needs no slope
  // bias, whose leaks at grazing angles it replaces (docs/shadow-maps.md, "Bias").
  // Ring bias: a tap of the PCF kernel `ring` texels from its centre tap (ring = the larger of
  // its column and row distance) also gets ring x ring_bias texels of depth bias. An off-centre
  // tap stands for receiver points up to that far from the looked-up one; on a rough receiver
  // they rise towards the light where a planar one would not (a concave crease a texel away),
  // and without this a tap reading that rising ground darkens a lit point (acne no normal
  // offset removes). Real occluders stand far above the receiver, so this barely lights shadows.
  // Normal offset 0.8 and ring bias 4 are the defaults: on the terrain at 160 x 107 they leave 8
  // acne pixels (21 with offset 1 and no ring bias) and leak no more than before; a ring bias of
  // 8 leaves 2 but lights the shadows of casters close above their receiver
  // (tests/test_shadow_map_baselines.cpp, docs/shadow-maps.md, "Bias").
  double constant_bias = 1.0;
  double slope_bias = 0.0;
  double normal_offset = 0.8;
  double ring_bias = 4.0;
  ShadowMapProjection projection = ShadowMapProjection::Auto;
  // 0: the spot frustum is fitted around the view's visible points, so it shadows exactly what
  // a cube would (the light still shines everywhere). > 0: the light is a spotlight: a square
  // frustum of this full angle in degrees, aimed from the light centre at the centre of the
  // scene's bounds, and points outside it get no light (needs projection spot or auto, which
  // it makes a spot). The other techniques and the oracle know no spotlights: compare with them
  // only at 0.
  double spot_fov = 0.0;
  // Arvo & Aila 2003 (the thesis's publication P4, section 4.2): the spot frustum is drawn as a
  // volume into a stencil over the eye's depth buffer, and only pixels inside it are looked up;
  // the others get what a lookup outside the frustum gives. Same image, fewer lookups. Needs a
  // spot (with auto, it applies when auto picks one).
  bool stencil_limit = false;
};

}  // namespace penumbra
