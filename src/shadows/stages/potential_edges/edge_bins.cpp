#include "shadows/stages/potential_edges/edge_bins.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include "core/parallel.h"

namespace penumbra {

namespace {

// The normalised-device x, y extent of clip-space points (all in front of the near plane).
struct NdcBox {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  void extend(const dvec4& clip) {
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  bool empty() const { return x0 > x1; }
};

// Items per work item: at most kChunk, and a 64th of the items down to kMinChunk, so that a
// frame with a few hundred edges (`columns`' silhouette) still spreads over the threads. The
// lists do not depend on it: chunks are merged in order, then counting-sorted by tile.
constexpr size_t kChunk = 2048, kMinChunk = 16;

// A world plane as a function of screen position and reversed-Z depth, E = value / w
// (wedge_screen.h, toScreenPlane), in double.
struct ScreenPlaneD {
  double a, b, c, d;
};

// Triangles of an edge whose signs the tile test looks at; an edge with more is not culled by
// its silhouette.
constexpr int kMaxTileTriangles = 4;

struct Region {
  std::array<ScreenPlaneD, kMaxRegionPlanes> planes;
  int plane_count = 0;
  // The edge's triangles' planes, for the silhouette test (EdgeTriangle); triangle_count 0
  // when there are more than kMaxTileTriangles. The tile test uses them only when no triangle
  // cuts the light (EdgeScreenTest::any_cuts); the pixels' quick reject always.
  std::array<ScreenPlaneD, kMaxTileTriangles> triangles;
  std::array<const EdgeTriangle*, kMaxTileTriangles> triangle;
  int triangle_count = 0;
  int tx0 = 0, ty0 = 0, tx1 = -1, ty1 = -1;  // tiles of the screen box, inclusive
};

class RegionBuilder {
 public:
  RegionBuilder(const Light& light, const View& view, int level, bool bounded,
                const dvec3& reach_min, const dvec3& reach_max)
      : c_(light.center), r_(light.radius), width_(view.width), height_(view.height),
        level_(level), near_(0.5 * double(view.near_plane)), reach_min_(reach_min),
        reach_max_(reach_max), bounded_(bounded) {
    vp_ = dmat4(view.view_projection);
    plane_to_clip_ = glm::transpose(glm::inverse(vp_));
  }

  Region region(const PotentialEdge& e, const EdgeTriangle* triangles) const {
    Region region;
    if (e.triangle_count <= uint32_t(kMaxTileTriangles)) {
      for (uint32_t k = 0; k < e.triangle_count; ++k) {
        const EdgeTriangle& t = triangles[e.first_triangle + k];
        region.triangles[k] = screenPlane(t.normal, t.offset);
        region.triangle[k] = &t;
      }
      region.triangle_count = int(e.triangle_count);
    }
    const dvec3 a = e.a, b = e.b;
    // The pyramid first (see below): of the points the tile test lets through, it rejects most,
    // so the rejects, which stop once no point is left, mostly evaluate it alone.
    pyramid(region, 0.5 * (a + b), 0.5 * glm::length(b - a));
    const dvec3 u = glm::normalize(b - a);
    // The two planes through the edge's line tangent to the ball: seen along the edge, the
    // region is the cone of rays from the edge away from the light's disk.
    const dvec3 ca = c_ - a;
    const dvec3 c_perp = ca - glm::dot(ca, u) * u;
    const double h = glm::length(c_perp);
    if (h > r_ * (1.0 + 1e-9)) {
      const dvec3 e1 = c_perp / h, e2 = glm::cross(u, e1);
      const double sin_beta = r_ / h, cos_beta = std::sqrt(1.0 - sin_beta * sin_beta);
      add(region, -sin_beta * e1 + cos_beta * e2, a);
      add(region, -sin_beta * e1 - cos_beta * e2, a);
    }
    // At each end a plane with the edge on its inner side and the ball on its outer side: the
    // shadow cone of the end point then lies inside, and so do the rays through every other
    // point of the edge (docs/exact-soft-shadows.md).
    endPlane(region, a, u);
    endPlane(region, b, -u);
    // Those planes leave a wide region for an edge whose line passes near the ball (no
    // tangent planes and a half-space where it passes through), so the region is also bounded
    // as that of the ball around the edge (the pyramid, added first).
    const dvec3 ends[2] = {a, b};
    screenBox(region, ends, 2);
    return region;
  }

  // A triangle whose plane cuts the light: the points some segment from the light through it
  // reaches, bounded by the pyramid around a ball holding the triangle.
  Region region(const CuttingTriangle& t) const {
    Region region;
    for (int k = 0; k < t.region_count; ++k) {
      region.planes[size_t(region.plane_count++)] =
          screenPlane(dvec3(t.region[size_t(k)]), t.region[size_t(k)].w);
    }
    screenBox(region, t.v, 3);
    return region;
  }

 private:
  // The region of anything inside a ball of radius rho around m (circumscribedPyramid).
  void pyramid(Region& region, const dvec3& m, double rho) const {
    dvec4 planes[4];
    const int count = circumscribedPyramid(c_, r_, m, rho, planes);
    for (int k = 0; k < count; ++k) {
      region.planes[size_t(region.plane_count++)] = screenPlane(dvec3(planes[k]), planes[k].w);
    }
  }

  ScreenPlaneD screenPlane(const dvec3& n, double offset) const {
    const dvec4 q = plane_to_clip_ * dvec4(n, offset);
    return ScreenPlaneD{2.0 * q.x / width_, -2.0 * q.y / height_, q.z, q.w - q.x + q.y};
  }
  void add(Region& region, const dvec3& n, const dvec3& through) const {
    region.planes[size_t(region.plane_count++)] = screenPlane(n, -glm::dot(n, through));
  }

  void endPlane(Region& region, const dvec3& end, const dvec3& inward) const {
    const dvec3 away = end - c_;
    const double distance = glm::length(away);
    if (!(distance > r_ * (1.0 + 1e-9))) return;
    const dvec3 w = away / distance;
    const double sin_alpha = r_ / distance, cos_alpha = std::sqrt(1.0 - sin_alpha * sin_alpha);
    // Need dot(n, inward) >= 0 and dot(n, w) >= sin_alpha (the end's shadow cone inside).
    if (glm::dot(inward, w) >= sin_alpha) {
      add(region, inward, end);
      return;
    }
    const dvec3 v = inward - glm::dot(inward, w) * w;
    const double v_length = glm::length(v);
    if (!(v_length > 1e-12)) return;
    const dvec3 n = sin_alpha * w + cos_alpha * (v / v_length);
    if (glm::dot(n, inward) >= 0.0) add(region, n, end);
  }

  // The screen box of the region's part in front of the eye: the region lies in the convex
  // hull of the edge's (or triangle's) corners and the shadow cones of the corners (a point
  // x + t (x - q) of the shadow is the same blend of the corners' shadow points), each cone
  // inside a square pyramid of four directions. Vertices of the hull cut at w = near are the
  // corners in front of it and the crossings of its edges with it; directions away from the
  // eye add their vanishing points. A cone with directions both toward and away from the eye
  // reaches the screen's border, so the box is the whole screen then. Only the part where a
  // shaded point can be matters, inside the reach box (boundedBox): that cuts the cones off
  // where they leave the scene, before their vanishing points.
  void screenBox(Region& region, const dvec3* ends, int end_count) const {
    std::array<dvec4, 3> points;
    std::array<dvec4, 12> directions;
    std::array<dvec3, 12> world_directions;  // the same, in world space
    bool full = false;
    for (int k = 0; k < end_count && !full; ++k) {
      const dvec3 end = ends[k];
      points[size_t(k)] = vp_ * dvec4(end, 1.0);
      const dvec3 away = end - c_;
      const double distance = glm::length(away);
      if (!(distance > r_ * (1.0 + 1e-9))) {
        full = true;
        break;
      }
      const dvec3 w = away / distance;
      const double sin_alpha = r_ / distance;
      const double tan_alpha = sin_alpha / std::sqrt(1.0 - sin_alpha * sin_alpha);
      const dvec3 helper = std::fabs(w.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
      const dvec3 t1 = glm::normalize(glm::cross(w, helper)), t2 = glm::cross(w, t1);
      // A little wider than the circumscribed pyramid, for rounding.
      const double spread = tan_alpha * (1.0 + 1e-6) + 1e-9;
      for (int s = 0; s < 4; ++s) {
        const dvec3 d = w + spread * ((s & 1 ? 1.0 : -1.0) * t1 + (s & 2 ? 1.0 : -1.0) * t2);
        world_directions[size_t(k * 4 + s)] = d;
        directions[size_t(k * 4 + s)] = vp_ * dvec4(d, 0.0);
      }
    }
    const int direction_count = 4 * end_count;
    if (!full && bounded_ &&
        boundedBox(region, ends, end_count, points.data(), directions.data(),
                   world_directions.data()))
      return;
    int positive = 0, negative = 0;
    if (!full) {
      for (int k = 0; k < direction_count; ++k) {
        positive += directions[size_t(k)].w > 0.0;
        negative += directions[size_t(k)].w < 0.0;
      }
      full = positive != direction_count && negative != direction_count;
    }
    NdcBox box;
    auto extend = [&](const dvec4& clip) { box.extend(clip); };
    auto crossing = [&](const dvec4& from, const dvec4& step) {
      // from + t step at w = near, for t >= 0 (t <= 1 for a segment, checked by the caller).
      const double t = (near_ - from.w) / step.w;
      extend(from + t * step);
    };
    if (!full) {
      for (int k = 0; k < end_count; ++k) {
        const dvec4& p = points[size_t(k)];
        if (p.w >= near_) extend(p);
        for (int j = 0; j < direction_count; ++j) {
          const dvec4& d = directions[size_t(j)];
          if ((p.w < near_ && d.w > 0.0) || (p.w > near_ && d.w < 0.0)) crossing(p, d);
        }
        for (int j = k + 1; j < end_count; ++j) {
          const dvec4& q = points[size_t(j)];
          if ((p.w < near_) != (q.w < near_)) crossing(p, q - p);
        }
      }
      if (positive == direction_count)
        for (int j = 0; j < direction_count; ++j) extend(directions[size_t(j)]);
      if (box.empty()) return;  // nothing in front of the eye
    }
    if (full) {
      const int tile = 1 << level_;
      region.tx0 = region.ty0 = 0;
      region.tx1 = (width_ + tile - 1) / tile - 1;
      region.ty1 = (height_ + tile - 1) / tile - 1;
      return;
    }
    tileBox(region, box);
  }

  // The hull of the corners and their cones (4 directions each) cut by a slab: with a unit
  // w that every direction d moves along (w.d > 0) and h the reach box's largest w.x, every
  // point x = sum l_i v_i + sum m_j d_j of the hull with w.x <= h lies in the hull of the
  // corners v_i and the points v_i + (h - w.v_i) / (w.d_j) d_j (split the m_j among the
  // corners in proportion to l_i (h - w.v_i)), so that finite hull, cut at w = near, bounds
  // the region's part inside the reach box. Of the slabs the box's six faces and the
  // direction away from the light give, the one with the shortest cones is taken (a floor
  // under a shadow cuts it where it lands). False when none fits (a cone too wide, a corner
  // beyond every slab): the unbounded hull's box is used then.
  bool boundedBox(Region& region, const dvec3* ends, int end_count, const dvec4* points,
                  const dvec4* directions, const dvec3* world_directions) const {
    const int direction_count = 4 * end_count;
    dvec3 candidates[7] = {dvec3(1, 0, 0), dvec3(-1, 0, 0), dvec3(0, 1, 0), dvec3(0, -1, 0),
                           dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(0.0)};
    for (int k = 0; k < end_count; ++k) candidates[6] += glm::normalize(ends[k] - c_);
    double direction_length[12];
    for (int j = 0; j < direction_count; ++j)
      direction_length[j] = glm::length(world_directions[j]);
    double best_length = std::numeric_limits<double>::infinity();
    dvec3 w(0.0);
    double h = 0.0;
    for (const dvec3& candidate : candidates) {
      const double length = glm::length(candidate);
      if (!(length > 1e-9)) continue;
      const dvec3 u = candidate / length;
      const double top = glm::dot(glm::max(u, dvec3(0.0)), reach_max_) +
                         glm::dot(glm::min(u, dvec3(0.0)), reach_min_);
      // The largest cone parameter (h - w.v) / (w.d) over the corners v and directions d. Every
      // direction must move along w and every corner lie below h; division is monotone, so the
      // largest quotient is the largest gap over the smallest step, the same double.
      bool usable = true;
      double smallest_along = std::numeric_limits<double>::infinity(), largest_gap = 0.0;
      for (int j = 0; j < direction_count && usable; ++j) {
        const double along = glm::dot(u, world_directions[j]);
        usable = along > 1e-6 * direction_length[j];
        smallest_along = std::min(smallest_along, along);
      }
      for (int k = 0; k < end_count && usable; ++k) {
        const double gap = top - glm::dot(u, ends[k]);
        usable = gap >= 0.0;
        largest_gap = std::max(largest_gap, gap);
      }
      if (!usable) continue;
      const double longest = largest_gap / smallest_along;
      if (longest < best_length) {
        best_length = longest;
        w = u;
        h = top;
      }
    }
    if (!(best_length < std::numeric_limits<double>::infinity())) return false;
    // Hull points in clip space (linear in the world point).
    std::array<dvec4, 3 + 3 * 12> hull;
    int count = 0;
    for (int k = 0; k < end_count; ++k) {
      const double gap = h - glm::dot(w, ends[k]);
      hull[size_t(count++)] = points[k];
      for (int j = 0; j < direction_count; ++j)
        hull[size_t(count++)] =
            points[k] + (gap / glm::dot(w, world_directions[j])) * directions[j];
    }
    NdcBox box;
    auto extend = [&](const dvec4& clip) { box.extend(clip); };
    // The hull cut at w = near: the points in front and the crossings of the segments
    // between a point in front and one behind.
    bool behind = false;
    for (int i = 0; i < count; ++i) {
      if (hull[size_t(i)].w >= near_) extend(hull[size_t(i)]);
      behind |= hull[size_t(i)].w < near_;
    }
    if (behind) {
      for (int i = 0; i < count; ++i) {
        for (int j = i + 1; j < count; ++j) {
          const dvec4& p = hull[size_t(i)];
          const dvec4& q = hull[size_t(j)];
          if ((p.w < near_) == (q.w < near_)) continue;
          extend(p + ((near_ - p.w) / (q.w - p.w)) * (q - p));
        }
      }
    }
    if (!box.empty()) tileBox(region, box);  // else nothing in front of the eye
    return true;
  }

  // The tiles of an NDC box.
  void tileBox(Region& region, const NdcBox& box) const {
    const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
    const int tile = 1 << level_;
    const int columns = (width_ + tile - 1) / tile, rows = (height_ + tile - 1) / tile;
    // NDC to pixels (y down), one pixel of slack, clamped before the conversion to int.
    const double px0 = (x0 + 1.0) * 0.5 * width_ - 1.0, px1 = (x1 + 1.0) * 0.5 * width_ + 1.0;
    const double py0 = (1.0 - y1) * 0.5 * height_ - 1.0, py1 = (1.0 - y0) * 0.5 * height_ + 1.0;
    if (px1 < 0.0 || py1 < 0.0 || px0 >= width_ || py0 >= height_) return;
    region.tx0 = int(std::max(0.0, px0)) / tile;
    region.ty0 = int(std::max(0.0, py0)) / tile;
    region.tx1 = std::min(int(std::min(px1, double(width_ - 1))) / tile, columns - 1);
    region.ty1 = std::min(int(std::min(py1, double(height_ - 1))) / tile, rows - 1);
  }

  dvec3 c_;
  double r_;
  int width_, height_, level_;
  double near_;
  dvec3 reach_min_, reach_max_;  // a box holding every shaded point
  bool bounded_;                 // false: no such box is known
  dmat4 vp_, plane_to_clip_;
};

}  // namespace

void addBinnedEdgeCounts(const EdgeBins& bins, Image<float>& layer) {
  const size_t tiles = size_t(bins.columns) * size_t(bins.rows);
  for (size_t index = 0; index < tiles; ++index) {
    const EdgeBinTile tile = edgeBinTile(bins, index, layer.width(), layer.height());
    const float count = float(tile.end - tile.begin);
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x) layer.at(x, y) += count;
  }
}

TileDepthParts tileDepthParts(const DepthBuffer& depth, int level) {
  const int tile = 1 << level;
  const int width = depth.width(), height = depth.height();
  const TileDepthRange& range = depth.tileRange(level);
  const int columns = (width + tile - 1) / tile, rows = (height + tile - 1) / tile;
  const size_t entries = size_t(columns) * size_t(rows) + kTileBoxPadding;
  TileDepthParts parts;
  parts.low_zmin.assign(entries, 0.0f);
  parts.low_zmax.assign(entries, 0.0f);
  parts.high_zmin.assign(entries, 0.0f);
  parts.high_zmax.assign(entries, 0.0f);
  parallelFor(size_t(rows), [&](size_t ty) {
    const int y0 = int(ty) * tile, y1 = std::min(height, y0 + tile);
    for (int tx = 0; tx < columns; ++tx) {
      const float zmin = range.zmin.at(tx, int(ty)), zmax = range.zmax.at(tx, int(ty));
      if (!(zmax > 0.0f)) continue;  // only background
      // Split at the middle of the tile's range (background, depth 0, included: any split
      // point is correct, and this one needs no pass of its own).
      const float middle = zmin + 0.5f * (zmax - zmin);
      const int x0 = tx * tile, x1 = std::min(width, x0 + tile);
      float low_lo = FLT_MAX, low_hi = 0.0f, high_lo = FLT_MAX, high_hi = 0.0f;
      for (int y = y0; y < y1; ++y) {
        const float* row = depth.depth.row(y);
        for (int x = x0; x < x1; ++x) {
          const float d = row[x];
          const bool surface = d > 0.0f, high = d > middle;
          // Branch-free: which part a pixel falls in follows no pattern.
          low_lo = surface && !high ? std::min(low_lo, d) : low_lo;
          low_hi = surface && !high ? std::max(low_hi, d) : low_hi;
          high_lo = high ? std::min(high_lo, d) : high_lo;
          high_hi = high ? std::max(high_hi, d) : high_hi;
        }
      }
      const size_t i = ty * size_t(columns) + size_t(tx);
      if (low_hi > 0.0f) parts.low_zmin[i] = low_lo, parts.low_zmax[i] = low_hi;
      if (high_hi > 0.0f) parts.high_zmin[i] = high_lo, parts.high_zmax[i] = high_hi;
    }
  });
  return parts;
}

namespace {

// The float planes of the quick reject, and each one's margin: the float evaluation error of E
// at any pixel centre of the image with z in [0, 1], four roundings, each within FLT_EPSILON
// of the terms' magnitudes (wedge_culling.cpp). The shaded point's offset is added per pixel
// (PixelBlock::offset) or per tile row.
struct FloatPlanes {
  double x_max, y_max;
  void operator()(const ScreenPlaneD& p, float out[4], float& plane_margin) const {
    out[0] = float(p.a);
    out[1] = float(p.b);
    out[2] = float(p.c);
    out[3] = float(p.d);
    plane_margin = float(8.0 * FLT_EPSILON * (std::fabs(p.a) * x_max + std::fabs(p.b) * y_max +
                                              std::fabs(p.c) + std::fabs(p.d)));
  }
};

// How far every shaded point can lie outside the scene's box: margin_footprints pixel
// footprints (distance to the eye times the pixel angle) of a visible point, taken at the
// box's farthest corner, and a little more for rounding.
double boundsPad(const dvec3& bounds_min, const dvec3& bounds_max, const View& view,
                 double margin_footprints, double pixel_angle) {
  const dvec3 eye(view.eye);
  const double farthest =
      glm::length(glm::max(glm::abs(bounds_min - eye), glm::abs(bounds_max - eye)));
  return margin_footprints * pixel_angle * farthest * 1.01 +
         1e-6 * (glm::length(bounds_max - bounds_min) + glm::length(eye) + farthest);
}

// An edge's quick-reject record (EdgeScreenTest) from its region: the region's planes, and per
// triangle its plane, side of the light, cut flag, weight and extent from the light centre.
void fillEdgeTest(const Region& region, const PotentialEdge& e, const Light& light,
                  const FloatPlanes& toFloat, EdgeScreenTest& test) {
  const dvec3 light_centre(light.center);
  test.region_count = int8_t(region.plane_count);
  for (int k = 0; k < region.plane_count; ++k)
    toFloat(region.planes[size_t(k)], test.region[k], test.region_margin[k]);
  test.triangle_count = int8_t(region.triangle_count);
  auto fromLight = [&](const dvec3& v, float out[3]) {
    const dvec3 d = v - light_centre;
    out[0] = float(d.x);
    out[1] = float(d.y);
    out[2] = float(d.z);
    return glm::length(d);
  };
  const double ends_extent = std::max(fromLight(e.a, test.ends[0]), fromLight(e.b, test.ends[1]));
  for (int k = 0; k < region.triangle_count; ++k) {
    const EdgeTriangle& t = *region.triangle[size_t(k)];
    toFloat(region.triangles[size_t(k)], test.triangle[k], test.triangle_margin[k]);
    test.light_above[k] = t.light_above;
    test.cuts[k] = t.cuts;
    test.any_cuts |= t.cuts;
    // A cutting triangle in front of the light counts on either side: -winding where its plane
    // value is positive, +winding where negative (edgeAtPixel: weight -= winding * sign); the
    // kernel adds `weight` on the positive side and subtracts it on the other.
    test.weight[k] = int8_t(t.cuts ? -t.winding : t.light_above ? t.winding : -t.winding);
    const double extent = std::max(ends_extent, fromLight(t.opposite, test.opposite[k]));
    test.cut_extent[k] = float((extent + double(light.radius)) * (1.0 + 1e-6));
  }
}

// The coarse tiles of a TileScan: each holds 2^step x 2^step bin tiles; its depth range is the
// hull of theirs and each of its two depth parts the hull of the bin tiles' parts whose zmin
// falls on that side of the middle of its range, so every depth box the bin tiles' test
// evaluates lies inside one the coarse tile's test evaluates (and its pixel box inside the
// coarse tile's). The test evaluates each plane in float at the box corner that decides it;
// float rounding is monotone in each operand, so that value at a coarse tile's corner bounds
// the value at every one of its bin tiles' corners the same way, and a coarse tile the test
// culls holds no bin tile it would keep (the silhouette signs likewise: a sign known over the
// coarse box is the same sign over each bin tile's).
struct CoarseTiles {
  int step = 0;  // 0: no coarse level, every box scanned flat
  int columns = 0, rows = 0;
  std::vector<float> zmin, zmax;  // padded by kTileBoxPadding, as the bin tiles' arrays
  TileDepthParts depth_parts;
  EdgeTileParts parts{};
  // Bin tiles holding a covered pixel, summed over the rectangle from tile (0, 0) to (tx, ty)
  // exclusive: entry ty (columns + 1) + tx, with `columns` the bin tiles' columns.
  std::vector<uint32_t> covered_sum;
};

// What the scan of a region's tiles reads: the tiles' depth ranges (padded past the last tile
// for edgeTileCandidates), their depth parts, and the coarse tiles above them.
struct TileScan {
  std::vector<float> zmin, zmax;
  TileDepthParts depth_parts;
  EdgeTileParts parts;
  CoarseTiles coarse;
  EdgeTileBox box(const Region& region, const EdgeBins& bins, const View& view) const {
    EdgeTileBox box;
    box.zmin = zmin.data();
    box.zmax = zmax.data();
    box.columns = bins.columns;
    box.tx0 = region.tx0;
    box.tx1 = region.tx1;
    box.ty0 = region.ty0;
    box.ty1 = region.ty1;
    box.size = 1 << bins.level;
    box.width = view.width;
    box.height = view.height;
    box.offset = bins.offset;
    box.parts = &parts;
    return box;
  }
  // The bin tiles of `box` that hold a covered pixel (what the flat scan counts as tested).
  uint32_t coveredIn(const EdgeTileBox& box) const {
    const size_t stride = size_t(box.columns) + 1;
    auto at = [&](int tx, int ty) { return coarse.covered_sum[size_t(ty) * stride + size_t(tx)]; };
    return at(box.tx1 + 1, box.ty1 + 1) - at(box.tx0, box.ty1 + 1) - at(box.tx1 + 1, box.ty0) +
           at(box.tx0, box.ty0);
  }
};

// A part [lo, hi] (hi 0: none) widened into the hull [lo_out, hi_out] (hi_out 0: empty so far).
void extendPart(float lo, float hi, float& lo_out, float& hi_out) {
  if (!(hi > 0.0f)) return;
  lo_out = hi_out > 0.0f ? std::min(lo_out, lo) : lo;
  hi_out = std::max(hi_out, hi);
}

// The coarse tiles (CoarseTiles) of a scan's bin tiles, `columns` x `rows` of them.
void buildCoarseTiles(TileScan& scan, int columns, int rows, int step) {
  CoarseTiles& c = scan.coarse;
  c.step = step;
  const int span = 1 << step;
  c.columns = (columns + span - 1) / span;
  c.rows = (rows + span - 1) / span;
  const size_t entries = size_t(c.columns) * size_t(c.rows) + kTileBoxPadding;
  for (std::vector<float>* v : {&c.zmin, &c.zmax, &c.depth_parts.low_zmin,
                                &c.depth_parts.low_zmax, &c.depth_parts.high_zmin,
                                &c.depth_parts.high_zmax})
    v->assign(entries, 0.0f);
  const TileDepthParts& fine = scan.depth_parts;
  for (int cy = 0; cy < c.rows; ++cy) {
    for (int cx = 0; cx < c.columns; ++cx) {
      const int tx0 = cx * span, tx1 = std::min(columns, tx0 + span);
      const int ty0 = cy * span, ty1 = std::min(rows, ty0 + span);
      float lo = 0.0f, hi = 0.0f, part_lo = 0.0f, part_hi = 0.0f;
      for (int ty = ty0; ty < ty1; ++ty)
        for (int tx = tx0; tx < tx1; ++tx) {
          const size_t i = size_t(ty) * size_t(columns) + size_t(tx);
          extendPart(scan.zmin[i], scan.zmax[i], lo, hi);
          extendPart(fine.low_zmin[i], fine.low_zmax[i], part_lo, part_hi);
          extendPart(fine.high_zmin[i], fine.high_zmax[i], part_lo, part_hi);
        }
      const size_t k = size_t(cy) * size_t(c.columns) + size_t(cx);
      c.zmin[k] = lo;
      c.zmax[k] = hi;
      // Any split point is correct (each bin tile's part goes wholly into one hull).
      const float middle = part_lo + 0.5f * (part_hi - part_lo);
      float low_lo = 0.0f, low_hi = 0.0f, high_lo = 0.0f, high_hi = 0.0f;
      for (int ty = ty0; ty < ty1; ++ty)
        for (int tx = tx0; tx < tx1; ++tx) {
          const size_t i = size_t(ty) * size_t(columns) + size_t(tx);
          for (const auto& [part_min, part_max] :
               {std::pair(fine.low_zmin[i], fine.low_zmax[i]),
                std::pair(fine.high_zmin[i], fine.high_zmax[i])}) {
            if (part_min <= middle)
              extendPart(part_min, part_max, low_lo, low_hi);
            else
              extendPart(part_min, part_max, high_lo, high_hi);
          }
        }
      c.depth_parts.low_zmin[k] = low_lo;
      c.depth_parts.low_zmax[k] = low_hi;
      c.depth_parts.high_zmin[k] = high_lo;
      c.depth_parts.high_zmax[k] = high_hi;
    }
  }
  c.parts = c.depth_parts.view();
  const size_t stride = size_t(columns) + 1;
  c.covered_sum.assign(stride * (size_t(rows) + 1), 0);
  for (int ty = 0; ty < rows; ++ty) {
    uint32_t row_sum = 0;
    for (int tx = 0; tx < columns; ++tx) {
      row_sum += scan.zmax[size_t(ty) * size_t(columns) + size_t(tx)] > 0.0f;
      c.covered_sum[size_t(ty + 1) * stride + size_t(tx + 1)] =
          c.covered_sum[size_t(ty) * stride + size_t(tx + 1)] + row_sum;
    }
  }
}

// Bin tiles in a box, at least, before the coarse tiles are tested first: in a smaller box the
// coarse test costs about what it saves.
constexpr int kCoarseMinTiles = 32;

// The kept bin tiles of `box` (edgeTileCandidates: the same tiles, in row order within each run
// of coarse tiles, and the same `tested`): in a large box the coarse tiles are tested first and
// only the bin tiles of those kept, a run of kept coarse tiles in a row at a time. `coarse_kept`
// has room for every coarse tile.
int scanTiles(const EdgeScreenTest& test, const EdgeTileBox& box, const TileScan& scan,
              bool simd, uint32_t* kept, uint32_t* coarse_kept, int& tested) {
  const int step = scan.coarse.step;
  if (step == 0 || (box.tx1 - box.tx0 + 1) * (box.ty1 - box.ty0 + 1) < kCoarseMinTiles)
    return edgeTileCandidates(test, box, kept, tested, simd);
  tested = int(scan.coveredIn(box));
  EdgeTileBox coarse = box;
  coarse.zmin = scan.coarse.zmin.data();
  coarse.zmax = scan.coarse.zmax.data();
  coarse.columns = scan.coarse.columns;
  coarse.tx0 = box.tx0 >> step;
  coarse.tx1 = box.tx1 >> step;
  coarse.ty0 = box.ty0 >> step;
  coarse.ty1 = box.ty1 >> step;
  coarse.size = box.size << step;
  coarse.parts = box.parts != nullptr ? &scan.coarse.parts : nullptr;
  int coarse_tested = 0;
  const int coarse_count = edgeTileCandidates(test, coarse, coarse_kept, coarse_tested, simd);
  const uint32_t columns = uint32_t(coarse.columns);
  int count = 0;
  for (int k = 0; k < coarse_count;) {
    const uint32_t first = coarse_kept[k];
    int end = k + 1;
    while (end < coarse_count && coarse_kept[end] == coarse_kept[end - 1] + 1 &&
           coarse_kept[end] / columns == first / columns)
      ++end;
    const int cy = int(first / columns), cx0 = int(first % columns);
    const int cx1 = int(coarse_kept[end - 1] % columns);
    EdgeTileBox fine = box;
    fine.tx0 = std::max(box.tx0, cx0 << step);
    fine.tx1 = std::min(box.tx1, ((cx1 + 1) << step) - 1);
    fine.ty0 = std::max(box.ty0, cy << step);
    fine.ty1 = std::min(box.ty1, ((cy + 1) << step) - 1);
    int fine_tested = 0;
    count += edgeTileCandidates(test, fine, kept + count, fine_tested, simd);
    k = end;
  }
  return count;
}

// Bins `count` items, item i's region made by regionOf(i), into per-tile lists (ascending item
// order within a tile: chunks in order, then a counting sort by tile). Each region's screen
// box goes through the tile form of the pixels' quick reject (edgeTileCandidates): a SIMD scan
// of the box's tiles, row by row, of those in coarse tiles the same test keeps (scanTiles).
template <class RegionOf>
void binItems(size_t count, const RegionOf& regionOf, const std::vector<EdgeScreenTest>& tests,
              const TileScan& scan, const View& view, bool simd, EdgeBins& bins,
              std::vector<uint32_t>& begin, std::vector<uint32_t>& items) {
  struct Part {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (tile, item)
    uint64_t tested = 0, culled = 0;
  };
  const size_t tiles = size_t(bins.columns) * size_t(bins.rows);
  const size_t chunk_size = std::clamp(count / 64, kMinChunk, kChunk);
  const size_t chunks = (count + chunk_size - 1) / chunk_size;
  std::vector<Part> parts(chunks);
  parallelFor(chunks, [&](size_t chunk) {
    Part& part = parts[chunk];
    std::vector<uint32_t> kept(tiles);
    std::vector<uint32_t> coarse_kept(size_t(scan.coarse.columns) * size_t(scan.coarse.rows));
    const size_t end = std::min(count, (chunk + 1) * chunk_size);
    for (size_t i = chunk * chunk_size; i < end; ++i) {
      const Region region = regionOf(i);
      if (region.tx0 > region.tx1 || region.ty0 > region.ty1) continue;
      const EdgeTileBox box = scan.box(region, bins, view);
      int tested = 0;
      const int kept_count =
          scanTiles(tests[i], box, scan, simd, kept.data(), coarse_kept.data(), tested);
      part.tested += uint64_t(tested);
      part.culled += uint64_t(tested - kept_count);
      for (int k = 0; k < kept_count; ++k) part.pairs.emplace_back(kept[size_t(k)], uint32_t(i));
    }
  });
  begin.assign(tiles + 1, 0);
  for (const Part& part : parts) {
    for (const auto& [t, item] : part.pairs) ++begin[t + 1];
    bins.tiles_tested += part.tested;
    bins.tiles_culled += part.culled;
  }
  for (size_t t = 0; t < tiles; ++t) begin[t + 1] += begin[t];
  items.resize(begin[tiles]);
  std::vector<uint32_t> cursor(begin.begin(), begin.end() - 1);
  for (const Part& part : parts)
    for (const auto& [t, item] : part.pairs) items[cursor[t]++] = item;
}

}  // namespace

EdgeBins binEdges(const PotentialEdges& edges, const Light& light, const View& view,
                  const DepthBuffer& depth, int level, double margin_footprints,
                  const Bounds3& scene_bounds, bool simd, int coarse_step) {
  EdgeBins bins;
  bins.level = level;
  const int tile = 1 << level;
  bins.columns = (view.width + tile - 1) / tile;
  bins.rows = (view.height + tile - 1) / tile;
  // A point d world units off its depth-buffer point changes a plane value by at most d, and
  // E by d / w; the shaded points stay within margin_footprints * w * pixel angle.
  const double pixel_angle = 2.0 / (double(view.projection[1][1]) * view.height);
  const double margin = margin_footprints * pixel_angle;
  // In float for the quick reject, rounded up (the sums margin + offset it enters are rounded
  // once more, far inside the 8 FLT_EPSILON of the planes' own margins).
  bins.offset = float(margin * (1.0 + 1e-5));
  // The regions are cut to the scene's box, widened by how far a shaded point can lie off it.
  const bool bounded =
      !scene_bounds.empty() && isFinite(scene_bounds.min) && isFinite(scene_bounds.max);
  const dvec3 bounds_min = bounded ? dvec3(scene_bounds.min) : dvec3(0.0);
  const dvec3 bounds_max = bounded ? dvec3(scene_bounds.max) : dvec3(0.0);
  const double pad = boundsPad(bounds_min, bounds_max, view, margin_footprints, pixel_angle);
  const RegionBuilder builder(light, view, level, bounded, bounds_min - dvec3(pad),
                              bounds_max + dvec3(pad));
  bins.tests.resize(edges.edges.size());
  bins.cutting_tests.resize(edges.cutting.size());
  const FloatPlanes toFloat{view.width + 0.5, view.height + 0.5};
  TileScan scan;
  const TileDepthRange& range = depth.tileRange(level);
  scan.zmin.assign(range.zmin.size() + kTileBoxPadding, 0.0f);
  scan.zmax.assign(range.zmax.size() + kTileBoxPadding, 0.0f);
  std::copy_n(range.zmin.data(), range.zmin.size(), scan.zmin.begin());
  std::copy_n(range.zmax.data(), range.zmax.size(), scan.zmax.begin());
  scan.depth_parts = tileDepthParts(depth, level);
  scan.parts = scan.depth_parts.view();
  buildCoarseTiles(scan, bins.columns, bins.rows, std::clamp(coarse_step, 0, 4));
  binItems(
      edges.edges.size(),
      [&](size_t i) {
        const Region region = builder.region(edges.edges[i], edges.triangles.data());
        fillEdgeTest(region, edges.edges[i], light, toFloat, bins.tests[i]);
        return region;
      },
      bins.tests, scan, view, simd, bins, bins.begin, bins.edges);
  binItems(
      edges.cutting.size(),
      [&](size_t i) {
        const Region region = builder.region(edges.cutting[i]);
        EdgeScreenTest& test = bins.cutting_tests[i];
        test.region_count = int8_t(region.plane_count);
        for (int k = 0; k < region.plane_count; ++k)
          toFloat(region.planes[size_t(k)], test.region[k], test.region_margin[k]);
        return region;
      },
      bins.cutting_tests, scan, view, simd, bins, bins.cutting_begin, bins.cutting);
  return bins;
}

}  // namespace penumbra
