#pragma once
// The 2003 paper's coverage texture (Funk 2004, sections 2.1.3 and 3.1.3): each silhouette
// edge's covered fraction of the light precomputed over the edge's two end points once clipped
// to the light, n values per parameter, n^4 entries (the paper's n = 32 flattened to a
// 1024 x 1024 texture: row n r1 + r2, column n theta1 + theta2). Kept as an option against the
// exact area (shape_coverage.h), which is the default.
//
// Parameters: a disk's clipped end points in polar form (r in [0, 1], n values from 0 to 1
// inclusive; theta in [0, 2 pi), n values 2 pi k / n with the last cell wrapping back to 0:
// Funk's section 4.1 artifact was an angle rounded up to 2 pi and not wrapped); a rectangle's,
// scaled to the square [-1, 1]^2, in Cartesian form (n values from -1 to 1). One table serves
// every disk and one every rectangle: the fraction does not depend on the size or aspect
// (shape_coverage.h). Symmetries the report names: swapping the end points negates the entry
// and rotating both (any angle for a disk, quarter turns for a square) keeps it; the table
// stores all n^4 entries as the paper's texture does, and the symmetries are checked by tests.
//
// The fraction jumps by one where the edge's line passes through the light centre (the point
// crosses the hard quad's plane, and the hard pass jumps back), so entries whose cell straddles
// that line are wrong on one side; nearest lookup has the step artifacts of Funk's section 4.4,
// quadlinear (16 entries) smooths them away from the jump.
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "core/math.h"
#include "scene/light.h"
#include "shadows/coverage/shape_coverage.h"
#include "shadows/coverage_options.h"

namespace penumbra {

inline constexpr int kMinCoverageTableSize = 4, kMaxCoverageTableSize = 48;

class CoverageTableData {
 public:
  CoverageTableData(LightOutline outline, int n);
  int size() const { return n_; }
  LightOutline outline() const { return outline_; }
  // The fraction for homogeneous end points (disk_coverage_kernel.h): clipped exactly, then
  // looked up.
  float lookup(const dvec3& a, const dvec3& b, CoverageTable mode) const;
  // The fraction for end points already inside the light.
  float lookupInside(const dvec2& lo, const dvec2& hi, CoverageTable mode) const;
  // Entry (i0, j0, i1, j1): first point's (r or x, theta or y) indices, then the second's.
  float entry(int i0, int j0, int i1, int j1) const {
    return values_[((size_t(i0) * size_t(n_) + size_t(j0)) * size_t(n_) + size_t(i1)) *
                       size_t(n_) + size_t(j1)];
  }

 private:
  // Continuous table coordinates of a point: (u, v) in [0, n - 1] (angles in [0, n)).
  dvec2 coordinates(const dvec2& q) const;
  dvec2 point(int i, int j) const;  // the point an entry's indices stand for

  LightOutline outline_;
  int n_;
  std::vector<float> values_;
};

// Tables built on first use and kept (one per outline and size); safe to call from threads.
class CoverageTableCache {
 public:
  const CoverageTableData& get(const Light& light, int n);

 private:
  std::mutex mutex_;
  std::map<std::pair<int, int>, std::unique_ptr<CoverageTableData>> tables_;
};

}  // namespace penumbra
