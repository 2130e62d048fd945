#pragma once
// Options of the coverage soft shadow volumes (`coverage`). For typed access:
//   config.options<penumbra::CoverageOptions>().table = penumbra::CoverageTable::Quadlinear;
#include <string>

namespace penumbra {

// How each silhouette edge's covered fraction of the light is found (2003 soft shadow volumes;
// Funk 2004, section 3.1.3).
enum class CoverageTable {
  Analytic,    // no table: the exact area (circular segment, or polygon clipping), the default
  Nearest,     // the paper's 4D coverage table, nearest entry
  Quadlinear,  // the same table, interpolated over all four parameters (Funk, section 4.4)
};
std::string coverageTableName(CoverageTable table);  // "analytic", "nearest", "quadlinear"

struct CoverageOptions {
  CoverageTable table = CoverageTable::Analytic;
  // Entries per table parameter (the paper's n = 32: n^4 entries, a 1024 x 1024 texture).
  int table_size = 32;
  // Edges are binned to square tiles of 2^tile_level pixels and culled against each tile's
  // z-min/z-max (2004 paper, section 4); 3 is 8x8.
  int tile_level = 3;
  // Open meshes that face the light both ways also cast their other facing in a second pass,
  // the darker visibility kept (as WedgeOptions::other_facing_pass): rays through their holes.
  bool other_facing_pass = true;
};

}  // namespace penumbra
