#pragma once
// The light's image plane for the alias-free shadow map: where the eye samples land when seen
// from the light centre, and the grid of light-space tiles they are binned into (the irregular
// z-buffer's tiles; Aila's 2005 thesis, section 4.1, Figure 4.1b: the samples on the light's
// image plane, large empty areas between them).
//
// One frustum when every sample lies within kSingleFrustumHalfAngle of their mean direction
// from the light (a light off to the side of what the eye sees, the common case); else the six
// faces of a cube around the light, each sample on the face of its major axis (a light among the
// visible geometry, where no single plane can hold every direction). One frustum bins each
// triangle once, with no seams; the angle limit keeps the projected sample density within a
// factor 1 / cos^3 = 8 of itself across the plane. Either way each grid spans only the bounding
// rectangle of its own samples (a frustum fitted to the samples), so no tile lies where there
// is nothing to shadow.
//
// Projection of a light-relative direction d onto a grid: (d . u / d . axis, d . v / d . axis).
// The grids only decide which samples a triangle is tested against; the test itself is exact
// and made in 3D (occluder_test.h), so a grid's rounding can only cost work, never a pixel,
// as long as a triangle's tile range covers every sample it could contain: the sample
// rectangle is padded and a triangle's rectangle widened by a margin for that.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace penumbra {

inline constexpr double kSingleFrustumHalfAngleDegrees = 60.0;

struct LightGrid {
  dvec3 axis{0.0}, u{0.0}, v{0.0};  // orthonormal; axis points from the light into the frustum
  double u0 = 0, v0 = 0, u1 = 0, v1 = 0;  // the samples' projected bounds, padded
  int columns = 1, rows = 1;
  size_t first_tile = 0;  // index of its tile (0, 0) among all grids' tiles, row-major
  size_t samples = 0;
};

struct TileRange {
  int column0, row0, column1, row1;  // inclusive
};

class LightGrids {
 public:
  // d: the samples relative to the light centre (none zero). Every sample gets a grid, and the
  // grids are sized for about `tile_samples` samples per tile.
  LightGrids(const std::vector<dvec3>& d, int tile_samples);

  const std::vector<LightGrid>& grids() const { return grids_; }
  size_t tileCount() const { return tile_count_; }
  bool singleFrustum() const { return grids_.size() == 1; }
  // The tile of sample i of the constructor's list.
  size_t tileOf(size_t sample) const { return sample_tile_[sample]; }
  // The tiles of grid g a triangle (vertices relative to the light centre) could cover:
  // false when it misses the grid's frustum.
  bool tileRange(size_t g, const dvec3& a, const dvec3& b, const dvec3& c,
                 TileRange& range) const;

 private:
  std::vector<LightGrid> grids_;
  std::vector<uint32_t> sample_tile_;  // per sample, its tile within all grids
  size_t tile_count_ = 0;
};

}  // namespace penumbra
