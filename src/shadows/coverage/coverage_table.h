#pragma once
// The 2003 paper's coverage texture (Funk 2004, sections 2.1.3 and 3.1.3): each silhouette
// edge's covered fraction of the light precomputed over the edge's end points once clipped to
// the light, n values per parameter (the paper's n = 32: 32^4 entries flattened to a
// 1024 x 1024 texture). Kept as an option against the exact area (shape_coverage.h), which is
// the default. One table serves every disk and one every rectangle: the fraction does not
// depend on the size or aspect (shape_coverage.h).
//
// Rectangles (scaled to the square [-1, 1]^2): the paper's 4D table over the end points'
// Cartesian coordinates, n values from -1 to 1 each, n^4 entries.
// Disks (sphere and disk lights): the polar parameterisation of Funk's section 3.1.3 with the
// rotation symmetry his section 3.1.3 names applied: the fraction depends on the end points'
// radii and the angle between them only, so the table is 3D, (r0, r1, dtheta), n^3 entries
// (r in [0, 1], dtheta in [-pi, pi], n values each, both ends inclusive). The angle is the
// signed difference atan2(cross, dot), never an absolute angle, so there is no wrap to get
// wrong (Funk's section 4.1 artifact was an absolute angle rounded up to 2 pi); and the
// fraction's one jump, where the edge passes through the light centre (the point crosses the
// hard quad's plane and the hard pass jumps back), lies exactly at dtheta = +-pi, the table's
// ends, so no cell interpolates across it. The other symmetry (swapping the end points negates
// the entry) is not used; tests check both.
//
// The square table keeps the jump inside its cells: entries whose cell straddles the line
// through the centre are wrong on one side, which shows as thin lines along the hard shadow's
// boundary (docs/coverage-soft-shadows.md). Nearest lookup has the steps of Funk's section
// 4.4; quadlinear (trilinear for disks) interpolates 16 (8) entries.
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
  size_t entries() const { return values_.size(); }

 private:
  dvec2 squarePoint(int i, int j) const;  // the square's grid point (i, j)

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
