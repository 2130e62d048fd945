#include "shadows/stages/light_depth_maps/light_frustum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {
namespace {

// A fitted spot is widened by this fraction of its half angle's tangent, so that a point on
// the box's boundary is not lost to the rounding of its projection.
constexpr double kFitMargin = 1e-4;

// Any up vector not parallel to `axis`: the world axis least aligned with it.
dvec3 upFor(const dvec3& axis) {
  const dvec3 a = glm::abs(axis);
  if (a.x <= a.y && a.x <= a.z) return dvec3(1, 0, 0);
  if (a.y <= a.z) return dvec3(0, 1, 0);
  return dvec3(0, 0, 1);
}

// The box of the visible points of the eye pass (background pixels have depth 0).
std::optional<std::array<dvec3, 2>> visibleBox(const View& view, const EyeBuffers& eye) {
  const int width = eye.depth.depth.width(), height = eye.depth.depth.height();
  std::vector<std::array<dvec3, 2>> rows(size_t(height), {dvec3(INFINITY), dvec3(-INFINITY)});
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < width; ++x) {
      const float d = eye.depth.depth.at(x, y);
      if (!(d > 0.0f)) continue;
      const dvec3 p = view.unproject(x, y, d);
      rows[row][0] = glm::min(rows[row][0], p);
      rows[row][1] = glm::max(rows[row][1], p);
    }
  });
  std::array<dvec3, 2> box = {dvec3(INFINITY), dvec3(-INFINITY)};
  for (const auto& r : rows) {
    box[0] = glm::min(box[0], r[0]);
    box[1] = glm::max(box[1], r[1]);
  }
  if (box[0].x > box[1].x) return std::nullopt;
  return box;
}

// The spot from `centre` aimed at the box's centre that holds all its corners; nullopt when a
// corner is not in front of the light or the half angle's tangent exceeds `max_tan`.
std::optional<LightFace> fitSpot(const dvec3& centre, const std::array<dvec3, 2>& box,
                                 double max_tan) {
  const dvec3 towards = 0.5 * (box[0] + box[1]) - centre;
  if (!(glm::length(towards) > 0.0)) return std::nullopt;
  LightFace face;
  face.axis = glm::normalize(towards);
  face.up = upFor(face.axis);
  const dvec3 right = glm::normalize(glm::cross(face.axis, face.up));
  const dvec3 up = glm::cross(right, face.axis);
  double tan_half = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const dvec3 q(corner & 1 ? box[1].x : box[0].x, corner & 2 ? box[1].y : box[0].y,
                  corner & 4 ? box[1].z : box[0].z);
    const dvec3 d = q - centre;
    const double z = glm::dot(d, face.axis);
    if (!(z > 0.0)) return std::nullopt;
    tan_half = std::max({tan_half, std::fabs(glm::dot(d, right)) / z,
                         std::fabs(glm::dot(d, up)) / z});
  }
  // A box seen edge-on (a flat floor from straight above holds no height) still needs a frustum
  // of some width.
  face.tan_half = std::max(tan_half * (1.0 + kFitMargin), 1e-6);
  if (!(face.tan_half <= max_tan)) return std::nullopt;
  return face;
}

}  // namespace

LightFrustums chooseLightFrustums(const Scene& scene, const Light& light, const View& view,
                                  const EyeBuffers& eye, ShadowMapProjection projection,
                                  double spot_fov_degrees) {
  const dvec3 centre(light.center);
  LightFrustums result;
  if (spot_fov_degrees > 0.0) {
    PENUMBRA_CHECK(projection != ShadowMapProjection::Cube,
                   "--spot-fov {} makes the light a spotlight, which needs --projection spot or "
                   "auto, not cube",
                   spot_fov_degrees);
    const Bounds3 bounds = scene.bounds();
    dvec3 axis = bounds.empty() ? dvec3(0, -1, 0) : dvec3(bounds.center()) - centre;
    axis = glm::length(axis) > 0.0 ? glm::normalize(axis) : dvec3(0, -1, 0);
    result.faces.push_back(
        {axis, upFor(axis), std::tan(0.5 * spot_fov_degrees * 3.14159265358979323846 / 180.0)});
    result.spotlight = true;
    return result;
  }
  if (projection != ShadowMapProjection::Cube) {
    const auto box = visibleBox(view, eye);
    const double max_tan = projection == ShadowMapProjection::Spot ? 1e6 : kMaxFittedSpotTan;
    const std::optional<LightFace> spot = box ? fitSpot(centre, *box, max_tan) : std::nullopt;
    if (spot) {
      result.faces.push_back(*spot);
      return result;
    }
    PENUMBRA_CHECK(projection != ShadowMapProjection::Spot || !box,
                   "--projection spot: no single frustum from the light at ({}, {}, {}) holds "
                   "the view's visible points (the light is inside or beside their box); use auto or cube",
                   light.center.x, light.center.y, light.center.z);
    if (projection == ShadowMapProjection::Spot) {
      // Nothing visible: any frustum will do.
      result.faces.push_back({dvec3(0, -1, 0), dvec3(1, 0, 0), 1.0});
      return result;
    }
  }
  static constexpr std::array<std::array<double, 6>, 6> kCube = {{
      {1, 0, 0, 0, 1, 0},
      {-1, 0, 0, 0, 1, 0},
      {0, 1, 0, 0, 0, 1},
      {0, -1, 0, 0, 0, 1},
      {0, 0, 1, 0, 1, 0},
      {0, 0, -1, 0, 1, 0},
  }};
  for (const auto& f : kCube)
    result.faces.push_back({dvec3(f[0], f[1], f[2]), dvec3(f[3], f[4], f[5]), 1.0});
  return result;
}

}  // namespace penumbra
