// Percentage-closer soft shadows, Fernando 2005, in the map's texels. Map coordinates are
// tangents from the light centre (u = lateral offset / distance along the face's axis), one
// texel being 2 tan_half / size of them. Offsets are taken as perpendicular to the face's
// axis (the paper's planar light and parallel planes): exact at the map's centre, growing
// with the angle off it.
#include "shadows/pcss/pcss_filter.h"

#include <algorithm>
#include <cmath>

namespace penumbra {
namespace {

constexpr double kGoldenAngle = 2.399963229728653;  // radians: Vogel's spiral
constexpr double kTwoPi = 6.283185307179586;

// Texels from the projected point over which a light of radius R seen from a receiver at
// distance w may be hidden by an occluder at distance d: the cone from the receiver to the
// light's disk cuts the plane at d in a disk of tangent radius R (w - d) / (d w) around the
// receiver's own direction (Fernando 2005, "blocker search" and "penumbra estimation", which
// are this one similar-triangles relation, at d = the nearest occluder and at d = the average
// blocker).
double diskTexels(double radius, double w, double d, double texels_per_tangent) {
  return radius * (w - d) / (d * w) * texels_per_tangent;
}

// Calls fn(i, j, offset) for the n points of a Vogel spiral of `radius` texels around (sx, sy),
// turned by `rotation` turns: texel (i, j) holds the point, offset its distance in texels.
template <class Fn>
void forSpiral(double sx, double sy, double radius, int n, double rotation, Fn&& fn) {
  for (int k = 0; k < n; ++k) {
    const double r = radius * std::sqrt((k + 0.5) / n);
    const double a = k * kGoldenAngle + kTwoPi * rotation;
    fn(int(std::floor(sx + r * std::cos(a))), int(std::floor(sy + r * std::sin(a))), r);
  }
}

}  // namespace

std::vector<double> nearestOccluders(const LightDepthMaps& maps) {
  std::vector<double> nearest;
  for (const Image<float>& depth : maps.depth) {
    float largest = 0.0f;  // reversed-Z: the largest stored depth is the nearest occluder
    for (size_t i = 0; i < depth.size(); ++i) largest = std::max(largest, depth[i]);
    nearest.push_back(largest > 0.0f ? maps.near / double(largest) : INFINITY);
  }
  return nearest;
}

double pixelRotation(int x, int y) {
  uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return double(h >> 8) / double(1u << 24);
}

float pcssVisibility(const LightDepthMaps& maps, const MapPoint& m, double slope,
                     double rotation, const PcssSettings& s, uint64_t& reads,
                     double nearest_occluder) {
  const double w = m.w;
  const double texel = maps.texelSize(m.face, w);
  const double texels_per_tangent = maps.size / (2.0 * maps.tan_half[size_t(m.face)]);
  // A lookup `offset` texels away compares against the receiver less this bias (a plane of
  // slope `slope` rises by slope x offset texels there).
  const auto receiverAt = [&](double offset) {
    return w - texel * (s.constant_bias + s.slope_bias * slope * (offset + 0.5));
  };
  if (!(nearest_occluder < w)) return 1.0f;  // nothing in the face lies in front of p

  // 1. Blocker search over the disk through which the light can be hidden from p.
  const double search = std::min(diskTexels(s.radius, w, nearest_occluder, texels_per_tangent),
                                 double(maps.size));
  double blockers = 0.0;
  int found = 0;
  forSpiral(m.sx, m.sy, search, s.blocker_samples, rotation, [&](int i, int j, double offset) {
    const double d = maps.occluder(m.face, i, j);
    if (d < receiverAt(offset)) {
      blockers += d;
      ++found;
    }
  });
  reads += uint64_t(s.blocker_samples);
  if (found == 0) return 1.0f;
  if (found == s.blocker_samples && search == 0.0) return 0.0f;  // a point light: the plain map

  // 2. Penumbra estimate from the average blocker distance; 3. filter over it.
  const double average = blockers / found;
  const double filter =
      std::min(diskTexels(s.radius, w, average, texels_per_tangent), double(maps.size));
  int lit = 0;
  forSpiral(m.sx, m.sy, filter, s.filter_samples, rotation, [&](int i, int j, double offset) {
    lit += maps.occluder(m.face, i, j) >= receiverAt(offset);
  });
  reads += uint64_t(s.filter_samples);
  return float(lit) / float(s.filter_samples);
}

}  // namespace penumbra
