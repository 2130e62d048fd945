#pragma once
// Which frustums a shadow map draws from the light centre: a cube of six 90-degree faces, or one
// square spot frustum (Aila 2005 thesis, section 2.3: a single shadow map covers a limited field
// of view; omni-directional lights inside or near the view need several).
#include <vector>

#include "core/math.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/shadow_map_options.h"

namespace penumbra {

// One face: looks from the light centre along `axis` with `up`, a square frustum whose half
// angle has tangent `tan_half` (1 for a cube face).
struct LightFace {
  dvec3 axis, up;
  double tan_half = 1.0;
};

struct LightFrustums {
  std::vector<LightFace> faces;  // 6 (cube: +X, -X, +Y, -Y, +Z, -Z) or 1 (spot)
  bool cube() const { return faces.size() == 6; }
  // Spot only: the light is a spotlight (ShadowMapOptions::spot_fov > 0) and points outside its
  // frustum get no light; else the spot was fitted around every visible point.
  bool spotlight = false;
};

// The widest fitted spot that auto picks, as the tangent of its half angle (45 degrees, a cube
// face's): a wider spot spreads its texels over more angle than the cube faces do, and the cube
// wins (measured on `fractal`, whose visible terrain needs a spot of about 110 degrees).
inline constexpr double kMaxFittedSpotTan = 1.0;

// The frustums for `light` in this view. A fitted spot is aimed from the light centre at the
// box of the eye pass's visible points and holds it: every segment from the light to a visible
// point lies inside it, so every occluder that matters is drawn. Auto picks that spot when the
// light is outside the box and the spot's half angle is at most 45 degrees, else the cube.
// Throws penumbra::Error when projection is Spot, spot_fov is 0 and no spot can hold the box
// (the light inside it, or the box too wide), naming the light.
LightFrustums chooseLightFrustums(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, ShadowMapProjection projection,
                                  double spot_fov_degrees);

}  // namespace penumbra
