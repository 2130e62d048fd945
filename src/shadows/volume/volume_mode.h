#pragma once
// Choosing z-pass or z-fail per caster (Everitt & Kilgard 2002; thesis section 2.2: z-pass is
// only correct when the eye, more precisely the near-plane rectangle, is outside the volume).
#include "core/math.h"
#include "core/view.h"

namespace penumbra {

// True when a shadow volume cast from `light` by geometry within `caster` may contain part of
// the near-plane rectangle: the convex hull of the light and that rectangle (Lengyel's
// "occlusion pyramid") overlaps the caster's box. Conservative: false only when a separating
// plane proves the volume misses the rectangle.
bool mayContainNearPlane(const View& view, const vec3& light, const Bounds3& caster);

}  // namespace penumbra
