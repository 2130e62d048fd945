#pragma once
// Small open meshes for the caster-policy tests (silhouette.h): consistently oriented, not
// closed, built in the test so that no shared model is needed.
#include <cmath>
#include <vector>

#include "scene/shapes.h"

namespace penumbra::testing {

// A sphere of radius `radius` about `center` from polar angle `from` (radians from the north
// pole) up to the north pole, outward: a dome for from = pi / 2, a globe with a hole at the
// bottom for from near pi, closed for from = pi. Open along the rim at `from`.
inline Mesh openSphere(vec3 center, float radius, double from, int segments = 32, int bands = 16) {
  std::vector<vec2> profile;  // (radius, height), bottom to top
  for (int i = 0; i <= bands; ++i) {
    const double theta = from * (1.0 - double(i) / double(bands));
    // Radius exactly 0 at a pole, so that the lathe closes it.
    const double r = std::sin(theta) < 1e-9 ? 0.0 : std::sin(theta);
    profile.push_back(vec2(float(radius * r), float(radius * std::cos(theta))));
  }
  Mesh mesh = makeLathe(center, profile, segments);
  mesh.name = "open-sphere";
  return mesh;
}

}  // namespace penumbra::testing
