#include "shadows/stages/light_sampling/light_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "scene/light.h"

namespace penumbra {
namespace {

uint64_t splitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

StrataGrid strataGrid(int n) {
  PENUMBRA_CHECK(n >= 1, "sample count {} must be at least 1", n);
  int rows = int(std::sqrt(double(n)));
  while (rows > 1 && n % rows != 0) --rows;
  return StrataGrid{n / rows, rows};
}

PixelRandom::PixelRandom(uint64_t seed, uint32_t x, uint32_t y) {
  // Each input goes through a full SplitMix64 round before the next is mixed in, so nearby
  // pixels and seeds get unrelated streams.
  uint64_t h = seed;
  splitMix64(h);
  h ^= uint64_t(x) * 0xd6e8feb86659fd93ull;
  h = splitMix64(h);
  h ^= uint64_t(y) * 0xa0761d6478bd642full;
  state_ = splitMix64(h);
}

double PixelRandom::next() { return double(splitMix64(state_) >> 11) * 0x1.0p-53; }

DiskPoint concentricDisk(vec2 u) {
  constexpr float kQuarterPi = float(std::numbers::pi / 4.0);
  const float a = 2.0f * u.x - 1.0f;
  const float b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return DiskPoint{0.0f, 1.0f, 0.0f};
  // The larger of |a|, |b| is the radius; phi is linear along the square's edge. A negative
  // radius with phi in [-pi/4, 3pi/4) covers the other half of the disk.
  float radius, phi;
  if (std::abs(a) > std::abs(b)) {
    radius = a;
    phi = kQuarterPi * (b / a);
  } else {
    radius = b;
    phi = 2.0f * kQuarterPi - kQuarterPi * (a / b);
  }
  DiskPoint p;
  p.radius = std::abs(radius);
  const float sign = radius < 0.0f ? -1.0f : 1.0f;
  p.cos_phi = sign * std::cos(phi);
  p.sin_phi = sign * std::sin(phi);
  return p;
}

SphereCone makeSphereCone(const dvec3& from, const dvec3& center, double radius) {
  SphereCone cone;
  const dvec3 to_center = center - from;
  const double distance = glm::length(to_center);
  PENUMBRA_DCHECK(distance > radius && radius > 0.0);
  const dvec3 n = to_center / distance;
  // Orthonormal basis around the axis without a branch on a "not parallel" helper vector
  // (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  cone.axis = vec3(n);
  cone.tangent = vec3(dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x));
  cone.bitangent = vec3(dvec3(b, sign + n.y * n.y * a, -n.y));
  cone.distance = float(distance);
  cone.radius = float(radius);
  // 1 - sqrt(1 - s^2) = s^2 / (1 + sqrt(1 - s^2)): exact for tiny lights, where the direct
  // form would round to 0 and collapse every sample onto the axis.
  const double s2 = (radius / distance) * (radius / distance);
  cone.one_minus_cos_max = float(s2 / (1.0 + std::sqrt(std::max(0.0, 1.0 - s2))));
  return cone;
}

ConeSample sampleSphereCone(const SphereCone& cone, const DiskPoint& disk_point) {
  const float one_minus_cos = disk_point.radius * disk_point.radius * cone.one_minus_cos_max;
  const float cos_theta = 1.0f - one_minus_cos;
  // sin^2 = (1 - cos)(1 + cos), from 1 - cos so a tiny cone keeps its angle.
  const float sin2_theta = one_minus_cos * (2.0f - one_minus_cos);
  const float sin_theta = std::sqrt(sin2_theta);
  ConeSample sample;
  sample.direction = cone.axis * cos_theta + (cone.tangent * disk_point.cos_phi +
                                              cone.bitangent * disk_point.sin_phi) * sin_theta;
  // Nearest intersection with the sphere: t = d cos(theta) - sqrt(r^2 - d^2 sin^2(theta)).
  // At the cap's rim the root is 0 up to rounding, hence the clamp.
  const float d = cone.distance;
  const float root = std::sqrt(std::max(0.0f, cone.radius * cone.radius - d * d * sin2_theta));
  sample.distance = d * cos_theta - root;
  return sample;
}

void stratifiedSamples(int n, uint64_t seed, uint32_t x, uint32_t y, vec2* out) {
  const StrataGrid grid = strataGrid(n);
  PixelRandom random(seed, x, y);
  // The cell arithmetic is in double; rounding to float may put a sample on its cell's upper
  // edge (harmless) or on 1.0, which the clamp keeps inside the half-open square.
  constexpr float kBelowOne = 0x1.fffffep-1f;
  for (int row = 0; row < grid.rows; ++row) {
    for (int column = 0; column < grid.columns; ++column) {
      const float u = float((column + random.next()) / grid.columns);
      const float v = float((row + random.next()) / grid.rows);
      out[row * grid.columns + column] = vec2(std::min(u, kBelowOne), std::min(v, kBelowOne));
    }
  }
}

void fixedSamples(int n, uint64_t seed, vec2* out) { stratifiedSamples(n, seed, 0, 0, out); }

dvec3 planarLightPoint(const Light& light, vec2 u) {
  const dvec3 c(light.center);
  if (light.shape == LightShape::Rectangle) {
    return c + (double(u.x) - 0.5) * dvec3(light.edge_u) + (double(u.y) - 0.5) * dvec3(light.edge_v);
  }
  PENUMBRA_DCHECK(light.shape == LightShape::Disk);
  dvec3 t, b;
  planeBasis(glm::normalize(dvec3(light.normal)), t, b);
  const DiskPoint d = concentricDisk(u);
  const double r = double(light.radius) * double(d.radius);
  return c + r * (double(d.cos_phi) * t + double(d.sin_phi) * b);
}

}  // namespace penumbra
