#pragma once
// The hot loop of `pcss` (Fernando 2005): the blocker search, penumbra estimate and variable
// percentage-closer filter for a batch of points that land on one face of the light's depth
// maps, SIMD over the points (one double lane per point, each lane its own search and filter
// widths), with a scalar twin. Same conventions as map_lookup_kernel.h (double positions,
// int(floor()) texels clamped to the face, no FMA).
//
// Both steps sample a Vogel spiral turned per pixel. The spiral's own directions (k x the
// golden angle) are tabled once per frame and turned by the pixel's angle with the angle-sum
// formula, so a point costs one sine and cosine instead of one per sample.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"

namespace penumbra {

// n points of a Vogel spiral on the unit disk: point k at radius sqrt((k + 0.5) / n) and angle
// k x the golden angle.
struct VogelSpiral {
  explicit VogelSpiral(int n);
  int n = 0;
  std::vector<double> radius, cos, sin;
};

struct PcssFace {
  FaceTexels texels;
  double nearest = 0;             // nearestOccluders: no blocker is closer to the light
  double texels_per_tangent = 0;  // size / (2 tan_half)
};

struct PcssShape {
  double light_radius = 0;   // world units
  double constant_bias = 0;  // texels
  bool plane_test = false;  // PcssOccluderTest::Plane, else Depth
  const VogelSpiral* blocker = nullptr;
  const VogelSpiral* filter = nullptr;
};

// Per point, padded to a multiple of kLookupBlock: the projected position (texels) and
// distance w along the face's axis, the texel's world size at w, slope_bias x the receiver's
// slope, the pixel's turn of the spirals as its cosine and sine, and the receiver's plane
// (ReceiverPlane in shadow_map_lookup.h: a, step_x, step_y; read only for the plane test).
struct PcssPoints {
  const double *sx, *sy, *w, *texel, *slope_bias, *turn_cos, *turn_sin;
  const double *plane_a, *plane_x, *plane_y;
};

// visibility[p] for p in [0, n): 1 where nothing on the face lies in front of the point or no
// blocker is found; 0 where every blocker sample is one at a point light (search width 0);
// else the lit fraction of the filter's samples. Adds the depth-map reads to `reads`.
void pcssVisibility(const PcssFace& face, const PcssShape& shape, const PcssPoints& points,
                    float* visibility, size_t n, uint64_t& reads, bool simd);
void pcssVisibilityScalar(const PcssFace& face, const PcssShape& shape, const PcssPoints& points,
                          float* visibility, size_t n, uint64_t& reads);

// The last step of a point, shared by both twins: its visibility from the nearest-occluder
// test, the blocker count, the search width and the lit filter count.
inline float pcssFinish(const PcssFace& face, const PcssShape& shape, double w, double found,
                        double search, double lit, uint64_t& reads) {
  if (!(face.nearest < w)) return 1.0f;
  reads += uint64_t(shape.blocker->n);
  if (found == 0.0) return 1.0f;
  if (found == double(shape.blocker->n) && search == 0.0) return 0.0f;  // the plain map
  reads += uint64_t(shape.filter->n);
  return float(int(lit)) / float(shape.filter->n);
}

// Texels from the projected point over which a light of radius R seen from a receiver at
// distance w may be hidden by an occluder at distance d: the cone from the receiver to the
// light's disk cuts the plane at d in a disk of tangent radius R (w - d) / (d w) around the
// receiver's own direction (Fernando 2005, "blocker search" and "penumbra estimation", which
// are this one similar-triangles relation, at d = the nearest occluder and at d = the average
// blocker).
inline double diskTexels(double radius, double w, double d, double texels_per_tangent) {
  return radius * (w - d) / (d * w) * texels_per_tangent;
}

}  // namespace penumbra
