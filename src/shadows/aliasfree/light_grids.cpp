#include "shadows/aliasfree/light_grids.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/parallel.h"

namespace penumbra {
namespace {

// Tiles per grid side at most: 2048^2 tiles is already far more than the samples of a
// 1920 x 1080 frame at one sample per tile.
constexpr int kMaxGridSide = 2048;

// Samples per work item of the per-sample loops.
constexpr size_t kChunk = 8192;

// The sample rectangle grows by this fraction of its larger side (plus kAbsolutePad, in tangent
// units, for a rectangle of one sample): samples then lie strictly inside the frustum, away
// from the clipping planes. A triangle's projected rectangle grows by kTriangleMargin (same
// units) to cover the rounding of its clipping and projection (a few 1e-16 relative).
constexpr double kRelativePad = 1e-6;
constexpr double kAbsolutePad = 1e-9;
constexpr double kTriangleMargin = 1e-9;

// A clipped vertex this close to the light centre, relative to its distance, has no usable
// projection (the triangle passes by the light): the triangle then gets the whole grid.
constexpr double kMinAxisFraction = 1e-9;

struct CubeFace {
  dvec3 axis, u, v;
};
// +X, -X, +Y, -Y, +Z, -Z, each with a right-handed (u, v, axis) basis.
const std::array<CubeFace, 6> kCubeFaces = {{
    {dvec3(1, 0, 0), dvec3(0, 0, -1), dvec3(0, 1, 0)},
    {dvec3(-1, 0, 0), dvec3(0, 0, 1), dvec3(0, 1, 0)},
    {dvec3(0, 1, 0), dvec3(1, 0, 0), dvec3(0, 0, -1)},
    {dvec3(0, -1, 0), dvec3(1, 0, 0), dvec3(0, 0, 1)},
    {dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0)},
    {dvec3(0, 0, -1), dvec3(-1, 0, 0), dvec3(0, 1, 0)},
}};

// The face whose axis is d's major axis (the first on a tie), as the shadow map picks it.
int majorFace(const dvec3& d) {
  const dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

dvec2 project(const LightGrid& g, const dvec3& d) {
  const double w = glm::dot(d, g.axis);
  return dvec2(glm::dot(d, g.u) / w, glm::dot(d, g.v) / w);
}

int tileIndex(double value, double lo, double hi, int count) {
  const double t = (value - lo) / (hi - lo) * count;
  return std::clamp(int(std::floor(t)), 0, count - 1);
}

// Calls body(chunk, i) for every sample i, in fixed chunks of kChunk in parallel; sums kept
// per chunk and added chunk by chunk in order do not depend on the thread count.
template <class Body>
void forEachSampleChunked(size_t samples, const Body& body) {
  const size_t chunks = (samples + kChunk - 1) / kChunk;
  parallelFor(chunks, [&](size_t chunk) {
    const size_t end = std::min(samples, (chunk + 1) * kChunk);
    for (size_t i = chunk * kChunk; i < end; ++i) body(chunk, i);
  });
}

// True when one frustum around the samples' mean direction holds them all (no sample more
// than kSingleFrustumHalfAngleDegrees from it); `mean` is then its unit axis.
bool fitsSingleFrustum(const std::vector<dvec3>& d, dvec3& mean) {
  const size_t chunks = (d.size() + kChunk - 1) / kChunk;
  std::vector<dvec3> chunk_sum(chunks, dvec3(0.0));
  forEachSampleChunked(d.size(),
                       [&](size_t chunk, size_t i) { chunk_sum[chunk] += glm::normalize(d[i]); });
  mean = dvec3(0.0);
  for (const dvec3& sum : chunk_sum) mean += sum;
  const double cos_limit = std::cos(glm::radians(kSingleFrustumHalfAngleDegrees));
  if (!(!d.empty() && glm::length(mean) > 0.0)) return false;
  mean = glm::normalize(mean);
  std::vector<uint8_t> chunk_outside(chunks, 0);
  forEachSampleChunked(d.size(), [&](size_t chunk, size_t i) {
    if (!(glm::dot(d[i], mean) >= cos_limit * glm::length(d[i]))) chunk_outside[chunk] = 1;
  });
  return std::find(chunk_outside.begin(), chunk_outside.end(), 1) == chunk_outside.end();
}

// The frustum grid around unit axis `mean`: any u perpendicular to the axis, the world axis
// least aligned with it made orthogonal.
LightGrid frustumAround(const dvec3& mean) {
  LightGrid g;
  g.axis = mean;
  const dvec3 a = glm::abs(mean);
  const dvec3 helper = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0)
                       : a.y <= a.z            ? dvec3(0, 1, 0)
                                               : dvec3(0, 0, 1);
  g.u = glm::normalize(glm::cross(helper, mean));
  g.v = glm::cross(mean, g.u);
  return g;
}

// Grid g's rectangle from its samples' bounds [low, high], padded, and its tiles: about
// samples / tile_samples, as square as the rectangle allows, numbered from *tile_count on.
void sizeGrid(LightGrid& g, const dvec2& low, const dvec2& high, int tile_samples,
              size_t& tile_count) {
  g.first_tile = tile_count;
  if (g.samples == 0) {
    g.u0 = g.v0 = -1.0;
    g.u1 = g.v1 = 1.0;
    tile_count += 1;
    return;
  }
  const double pad = kRelativePad * std::max(high.x - low.x, high.y - low.y) + kAbsolutePad;
  g.u0 = low.x - pad;
  g.v0 = low.y - pad;
  g.u1 = high.x + pad;
  g.v1 = high.y + pad;
  const double tiles = std::max(1.0, double(g.samples) / double(tile_samples));
  const double aspect = (g.u1 - g.u0) / (g.v1 - g.v0);
  g.columns = std::clamp(int(std::lround(std::sqrt(tiles * aspect))), 1, kMaxGridSide);
  g.rows = std::clamp(int(std::lround(tiles / g.columns)), 1, kMaxGridSide);
  tile_count += size_t(g.columns) * size_t(g.rows);
}

// Each grid spans its samples' bounds, padded; empty grids keep one tile and no samples.
void fitGrids(const std::vector<dvec3>& d, const std::vector<uint8_t>& grid_of,
              int tile_samples, std::vector<LightGrid>& grids, size_t& tile_count) {
  const size_t chunks = (d.size() + kChunk - 1) / kChunk;
  const size_t n_grids = grids.size();
  std::vector<dvec2> lo(chunks * n_grids, dvec2(HUGE_VAL)), hi(chunks * n_grids, dvec2(-HUGE_VAL));
  std::vector<size_t> count(chunks * n_grids, 0);
  forEachSampleChunked(d.size(), [&](size_t chunk, size_t i) {
    const size_t k = chunk * n_grids + grid_of[i];
    const dvec2 uv = project(grids[grid_of[i]], d[i]);
    lo[k] = glm::min(lo[k], uv);
    hi[k] = glm::max(hi[k], uv);
    ++count[k];
  });
  for (size_t k = 0; k < n_grids; ++k) {
    LightGrid& g = grids[k];
    dvec2 low(HUGE_VAL), high(-HUGE_VAL);
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
      low = glm::min(low, lo[chunk * n_grids + k]);
      high = glm::max(high, hi[chunk * n_grids + k]);
      g.samples += count[chunk * n_grids + k];
    }
    sizeGrid(g, low, high, tile_samples, tile_count);
  }
}

}  // namespace

// The light's image plane of the irregular z-buffer (thesis section 4.1): one frustum, or six
// cube faces, sized to the samples; every sample's tile.
LightGrids::LightGrids(const std::vector<dvec3>& d, int tile_samples) {
  sample_tile_.resize(d.size());
  std::vector<uint8_t> grid_of(d.size(), 0);
  dvec3 mean;
  if (fitsSingleFrustum(d, mean)) {
    grids_.push_back(frustumAround(mean));
  } else {
    for (const CubeFace& f : kCubeFaces) {
      LightGrid g;
      g.axis = f.axis;
      g.u = f.u;
      g.v = f.v;
      grids_.push_back(g);
    }
    forEachSampleChunked(d.size(),
                         [&](size_t, size_t i) { grid_of[i] = uint8_t(majorFace(d[i])); });
  }
  fitGrids(d, grid_of, tile_samples, grids_, tile_count_);
  forEachSampleChunked(d.size(), [&](size_t, size_t i) {
    // Projected again rather than kept: the same operations give the same bits.
    const LightGrid& g = grids_[grid_of[i]];
    const dvec2 uv = project(g, d[i]);
    const int column = tileIndex(uv.x, g.u0, g.u1, g.columns);
    const int row = tileIndex(uv.y, g.v0, g.v1, g.rows);
    sample_tile_[i] = uint32_t(g.first_tile + size_t(row) * size_t(g.columns) + size_t(column));
  });
}

bool LightGrids::tileRange(size_t k, const dvec3& a, const dvec3& b, const dvec3& c,
                           TileRange& range) const {
  const LightGrid& g = grids_[k];
  if (g.samples == 0) return false;
  // The frustum through the sample rectangle: four planes through the light centre, d . n >= 0
  // inside. Together they also keep d . axis >= 0 (u0 < u1 and v0 < v1).
  const dvec3 planes[4] = {g.u - g.u0 * g.axis, g.u1 * g.axis - g.u, g.v - g.v0 * g.axis,
                           g.v1 * g.axis - g.v};
  // A triangle wholly outside one plane misses the frustum; one inside all four needs no
  // clipping (most triangles: the frustum is fitted to the samples, and the samples to the view).
  bool inside = true;
  for (const dvec3& n : planes) {
    const double fa = glm::dot(a, n), fb = glm::dot(b, n), fc = glm::dot(c, n);
    if (fa < 0.0 && fb < 0.0 && fc < 0.0) return false;
    inside = inside && fa >= 0.0 && fb >= 0.0 && fc >= 0.0;
  }
  // Sutherland-Hodgman: a triangle clipped by four planes keeps at most 7 vertices.
  std::array<dvec3, 8> polygon = {a, b, c}, next;
  int count = 3;
  for (const dvec3& n : planes) {
    if (inside) break;
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      const dvec3& p = polygon[i];
      const dvec3& q = polygon[(i + 1) % count];
      const double fp = glm::dot(p, n), fq = glm::dot(q, n);
      if (fp >= 0.0) next[kept++] = p;
      if ((fp >= 0.0) != (fq >= 0.0)) next[kept++] = p + (q - p) * (fp / (fp - fq));
    }
    polygon = next;
    count = kept;
    if (count == 0) return false;
  }
  dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  bool whole = false;
  for (int i = 0; i < count; ++i) {
    const double w = glm::dot(polygon[i], g.axis);
    if (!(w > kMinAxisFraction * glm::length(polygon[i]))) {
      whole = true;
      break;
    }
    const dvec2 p = project(g, polygon[i]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (whole || !std::isfinite(lo.x + lo.y + hi.x + hi.y)) {
    range = {0, 0, g.columns - 1, g.rows - 1};
    return true;
  }
  lo -= kTriangleMargin;
  hi += kTriangleMargin;
  if (hi.x < g.u0 || hi.y < g.v0 || lo.x > g.u1 || lo.y > g.v1) return false;
  range = {tileIndex(lo.x, g.u0, g.u1, g.columns), tileIndex(lo.y, g.v0, g.v1, g.rows),
           tileIndex(hi.x, g.u0, g.u1, g.columns), tileIndex(hi.y, g.v0, g.v1, g.rows)};
  return true;
}

}  // namespace penumbra
