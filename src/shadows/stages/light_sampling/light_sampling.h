#pragma once
// Stratified directions toward a spherical light, for the oracle's soft shadows.
//
// The light is a sphere, and from a point p the part of it p can see is a spherical cap; the
// light's contribution is the solid angle of the unblocked part of that cap over the whole
// cap's (constant radiance, no cosine or falloff weighting, as in the papers' visibility). So
// directions are sampled uniformly in solid angle inside the cone tangent to the sphere,
// cos(theta_max) = sqrt(1 - (r / d)^2). The papers approximate the sphere by a disk facing the
// point (an angular radius of atan(r / d) instead of asin(r / d), and uniform in disk area
// rather than in solid angle); that is their approximation, not the ground truth. The angular
// radii differ by about (r / d)^2 / 2 relative (3% at r / d = 1/4), so the two differ visibly
// only for lights close to the receiver.
//
// Random numbers are a pure function of (seed, pixel, sample): no global state, so a pixel's
// samples do not depend on which thread ran it or in what order.
#include <cmath>
#include <cstdint>

#include "core/math.h"

namespace penumbra {

// Strata for n samples: columns * rows == n with rows the largest divisor of n <= sqrt(n)
// (16 x 16 for 256; a prime n degenerates to n x 1, still stratified along one axis).
struct StrataGrid {
  int columns = 1;
  int rows = 1;
};
StrataGrid strataGrid(int n);

// Deterministic per-pixel random stream (SplitMix64 seeded by a hash of seed, x and y).
class PixelRandom {
 public:
  PixelRandom(uint64_t seed, uint32_t x, uint32_t y);
  double next();  // uniform in [0, 1), 53 random bits

 private:
  uint64_t state_;
};

// Per-sample work is in float: Embree takes float rays anyway, and the sqrt and sincos per
// sample in double are a large share of a soft render's time (bench/README.md).
// Per-pixel set-up (the cone) is computed in double and then rounded.

// A point of the unit disk in polar form.
struct DiskPoint {
  float radius;  // in [0, 1]
  float cos_phi;
  float sin_phi;
};

// Unit square [0, 1)^2 -> unit disk, area preserving (Shirley & Chiu's concentric map), so
// square strata become compact disk strata of equal area.
DiskPoint concentricDisk(vec2 u);

// The cone of directions from a point to a sphere it lies outside of.
struct SphereCone {
  vec3 axis;       // unit, from the point toward the sphere's centre
  vec3 tangent;    // unit, with `bitangent` and `axis` an orthonormal basis
  vec3 bitangent;
  float distance = 0;  // from the point to the centre, > radius
  float radius = 0;
  float one_minus_cos_max = 0;  // 1 - cos(theta_max), computed without cancellation
};
// Requires distance(from, center) > radius > 0 (the caller handles points inside the light).
SphereCone makeSphereCone(const dvec3& from, const dvec3& center, double radius);

struct ConeSample {
  vec3 direction;  // unit up to float rounding
  float distance;  // from the point to the sphere's near surface along `direction`
};
// Maps a point of the unit disk to a direction inside the cone, uniformly in solid angle: the
// disk radius squared is the fraction of the cap's solid angle (1 - cos theta) / (1 - cos max).
ConeSample sampleSphereCone(const SphereCone& cone, const DiskPoint& disk_point);

// n jittered stratified points in [0, 1)^2 for pixel (x, y): one uniformly placed point per
// cell of strataGrid(n), cells in row-major order.
void stratifiedSamples(int n, uint64_t seed, uint32_t x, uint32_t y, vec2* out);

// The one set of n samples every pixel shares in SampleSet::Fixed (reference_options.h) and in
// the exact soft shadow volumes: pixel (0, 0)'s stratified set for `seed`.
void fixedSamples(int n, uint64_t seed, vec2* out);

// A point of a disk or rectangle light (light.h) for a point of [0, 1)^2, uniform in area: the
// concentric map onto a disk, the square stretched onto a rectangle. Square strata become
// strata of equal area. (Spheres are sampled by direction, sampleSphereCone.)
struct Light;
dvec3 planarLightPoint(const Light& light, vec2 u);
// An orthonormal basis (tangent, bitangent) of the plane with unit normal n (Duff et al. 2017),
// right-handed: tangent x bitangent = n. Inline: the coverage technique sets one up per pixel.
inline void planeBasis(const dvec3& n, dvec3& tangent, dvec3& bitangent) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  tangent = dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  bitangent = dvec3(b, sign + n.y * n.y * a, -n.y);
}

}  // namespace penumbra
