#include "scene/teapot.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "scene/mesh_ops.h"
#include "scene/shapes.h"

namespace penumbra {

namespace {

// Designed in units where the teapot is kTeapotHeight tall; makeTeapot scales.
constexpr float kTeapotHeight = 0.98f;  // knob top; the spout mouth is lower
constexpr float kBodyHeight = 0.72f;

Mesh teapotBody() {
  // Bulging profile: radius 0.45 at the foot, ~0.67 at the belly, 0.42 at the rim.
  std::vector<vec2> profile = {vec2(0.0f, 0.0f)};
  constexpr int kSteps = 20;
  for (int i = 0; i <= kSteps; ++i) {
    const float t = float(i) / kSteps;
    const float r = 0.45f + 0.23f * std::sin(std::numbers::pi_v<float> * t) - 0.03f * t;
    profile.push_back(vec2(r, kBodyHeight * t));
  }
  profile.push_back(vec2(0.0f, kBodyHeight));
  return makeLathe(vec3(0.0f), profile, 40);
}

Mesh teapotLid() {
  // Starts inside the body (below its top) and rises to a lip overhanging the rim, a dome and a
  // knob on a short neck.
  const std::vector<vec2> profile = {
      vec2(0.0f, 0.69f),   vec2(0.40f, 0.69f),   vec2(0.455f, 0.73f), vec2(0.43f, 0.755f),
      vec2(0.37f, 0.79f),  vec2(0.28f, 0.82f),   vec2(0.16f, 0.84f),  vec2(0.065f, 0.85f),
      vec2(0.055f, 0.875f), vec2(0.095f, 0.905f), vec2(0.11f, 0.935f), vec2(0.085f, 0.965f),
      vec2(0.0f, kTeapotHeight)};
  return makeLathe(vec3(0.0f), profile, 32);
}

Mesh teapotSpout() {
  // A quadratic Bezier rising out of the belly, tapering, with a slight flare at the mouth.
  const vec3 p0(0.40f, 0.22f, 0.0f), p1(0.95f, 0.18f, 0.0f), p2(1.10f, 0.76f, 0.0f);
  std::vector<vec3> path;
  std::vector<float> radii;
  constexpr int kSteps = 18;
  for (int i = 0; i <= kSteps; ++i) {
    const float t = float(i) / kSteps;
    path.push_back((1 - t) * (1 - t) * p0 + 2 * (1 - t) * t * p1 + t * t * p2);
    radii.push_back(0.15f - 0.09f * t + (t > 0.9f ? 0.1f * (t - 0.9f) : 0.0f));
  }
  return makeTube(path, radii, 16, false);
}

Mesh teapotHandle() {
  // An elliptic arc on the -x side, entering the body at both ends.
  std::vector<vec3> path = {vec3(-0.45f, 0.60f, 0.0f)};
  constexpr int kSteps = 20;
  const float limit = glm::radians(80.0f);
  for (int i = 0; i <= kSteps; ++i) {
    const float phi = limit - 2.0f * limit * float(i) / kSteps;
    path.push_back(vec3(-0.62f - 0.24f * std::cos(phi), 0.38f + 0.22f * std::sin(phi), 0.0f));
  }
  path.push_back(vec3(-0.50f, 0.16f, 0.0f));
  return makeTube(path, std::vector<float>(path.size(), 0.05f), 12, false);
}

}  // namespace

Mesh makeTeapot(vec3 base_center, float height) {
  PENUMBRA_CHECK(height > 0.0f && std::isfinite(height), "teapot: height {} must be > 0", height);
  Mesh mesh;
  for (const Mesh& part : {teapotBody(), teapotLid(), teapotSpout(), teapotHandle()}) {
    appendMesh(mesh, part);
  }
  mesh.name = "teapot";
  const float scale = height / kTeapotHeight;
  transformMesh(mesh, glm::scale(glm::translate(mat4(1.0f), base_center), vec3(scale)));
  return mesh;
}

}  // namespace penumbra
