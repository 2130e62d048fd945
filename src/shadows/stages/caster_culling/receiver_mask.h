#pragma once
// The receivers of one light, seen from its centre: a pyramid of grids over the directions from
// the centre (a cube around it, six faces of kReceiverCells x kReceiverCells cells at the finest
// level, each coarser level halving the side), holding per cell the distance from the
// centre of the farthest visible point of the eye pass whose direction falls in it (-1 where
// none does). Bittner et al. 2011 (shadow caster culling) draw the receivers into a shadow-map
// sized mask; Lloyd et al. 2004 (CC shadow volumes) into a light-space depth bound. The
// directions make it one mask for a point light whatever its surroundings (no frustum to fit),
// and the farthest distance is what a caster must be nearer than to shadow anything there.
//
// A technique may shade a point up to kMaxOriginOffsetFootprints pixel footprints from its
// depth-buffer point (ray_origin.h: the oracle's origins, which exact and coverage share). So a
// receiver is that ball, not the point: each cell also holds a bound on the angle such a ball
// spans from the centre (asin(radius / distance)), and its distance is taken at the ball's far
// side (receiver_mask.cpp says how both are bounded cheaply).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/view.h"
#include "raster/depth_buffer.h"

namespace penumbra {

inline constexpr int kReceiverCells = 128;  // finest level: cells per face side

class ReceiverMask {
 public:
  // Every visible pixel of `eye` (primitive != kNoPrimitive), unprojected and binned by its
  // direction from `centre`, in parallel bands; points at the centre itself are left out (no
  // direction; only a caster within the light can shadow them, and those are never culled).
  ReceiverMask(const View& view, const EyeBuffers& eye, const dvec3& centre);

  // True when some cell whose directions come within `half_angle` (radians) of the unit
  // direction `axis` holds a receiver farther than `nearest` from the centre. Cells are tested
  // by their bounding cones, coarse to fine, so a caster costs a few dozen cells.
  bool anyFartherWithin(const dvec3& axis, double half_angle, double nearest) const;

  size_t receivers() const { return receivers_; }

 private:
  // Per level (0: finest), per face, row-major: how far the farthest receiver ball reaches, -1
  // if empty, and a bound on the ratio of a ball's radius to its distance (the sine of the
  // angle it spans).
  std::vector<std::vector<float>> farthest_;
  std::vector<std::vector<float>> spread_;
  size_t receivers_ = 0;
  bool visit(int level, int face, int i, int j, const dvec3& axis, double half_angle,
             double nearest) const;
};

}  // namespace penumbra
