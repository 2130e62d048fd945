#include "shadows/stages/caster_culling/receiver_mask.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/parallel.h"
#include "core/pixel_unprojector.h"
#include "shadows/stages/light_sampling/ray_origin.h"

namespace penumbra {
namespace {

constexpr int kFaces = 6;  // +x, -x, +y, -y, +z, -z

int levelCells(int level) { return kReceiverCells >> level; }
int levelCount() {
  int levels = 1;
  while ((kReceiverCells >> (levels - 1)) > 1) ++levels;
  return levels;
}

// The direction of face point (s, t), both in [-1, 1]: the face's axis is face / 2, its sign
// + for even faces, and s, t run along the next two axes in cyclic order.
dvec3 faceDirection(int face, double s, double t) {
  const int a = face / 2;
  dvec3 d(0.0);
  d[a] = (face % 2) == 0 ? 1.0 : -1.0;
  d[(a + 1) % 3] = s;
  d[(a + 2) % 3] = t;
  return d;
}

// The finest cell of direction d (not zero): its face and its (i, j).
size_t finestCell(const dvec3& d) {
  const dvec3 m = glm::abs(d);
  const int a = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  const int face = 2 * a + (d[a] < 0.0 ? 1 : 0);
  const double scale = 0.5 * kReceiverCells / m[a];
  const auto cell = [&](double v) {
    return std::clamp(int(std::floor((v * scale) + 0.5 * kReceiverCells)), 0, kReceiverCells - 1);
  };
  const int i = cell(d[(a + 1) % 3]), j = cell(d[(a + 2) % 3]);
  return (size_t(face) * kReceiverCells + size_t(j)) * kReceiverCells + size_t(i);
}

double angleBetween(const dvec3& a, const dvec3& b) {  // unit vectors
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// Per cell of one band of rows, what its receivers need (the mask's cells are made of these
// after the bands are merged): the largest and smallest squared distance from the centre and
// the largest ball radius, each rounded outward to float only when it changes the cell.
struct BandCells {
  std::vector<float> max_squared, min_squared, max_radius;
  explicit BandCells(size_t cells)
      : max_squared(cells, -1.0f), min_squared(cells, INFINITY), max_radius(cells, 0.0f) {}
  void add(size_t cell, double squared, double radius) {
    if (double(max_squared[cell]) < squared)
      max_squared[cell] = std::nextafter(float(squared), INFINITY);
    if (double(min_squared[cell]) > squared)
      min_squared[cell] = std::nextafter(float(squared), 0.0f);
    if (double(max_radius[cell]) < radius)
      max_radius[cell] = std::nextafter(float(radius), INFINITY);
  }
};

}  // namespace

ReceiverMask::ReceiverMask(const View& view, const EyeBuffers& eye, const dvec3& centre) {
  const size_t cells = size_t(kFaces) * kReceiverCells * kReceiverCells;
  // One grid per band of rows, merged after: maxima and minima do not depend on the bands, so
  // the mask is the same for any thread count.
  const size_t bands = std::clamp<size_t>(size_t(2 * workerCount()), 1,
                                          std::max<size_t>(1, size_t(view.height)));
  std::vector<BandCells> band_cells;
  band_cells.reserve(bands);
  for (size_t band = 0; band < bands; ++band) band_cells.emplace_back(cells);
  std::vector<size_t> band_receivers(bands, 0);
  const PixelUnprojector unproject(view);
  // A receiver's ball radius, per unit of its view depth w = near / stored depth: the pixel
  // footprint (distance to the eye times the pixel angle at the image centre, bounded above by
  // its tangent-plane size) times kMaxOriginOffsetFootprints, the distance to the eye bounded
  // by w times the longest pixel ray (at a corner of the image), with 1 % to spare.
  const double p00 = double(view.projection[0][0]), p11 = double(view.projection[1][1]);
  const double radius_per_w =
      1.01 * kMaxOriginOffsetFootprints *
      std::max(2.0 / (p00 * view.width), 2.0 / (p11 * view.height)) *
      std::sqrt(1.0 + 1.0 / (p00 * p00) + 1.0 / (p11 * p11));
  const double near_plane = double(view.near_plane);
  parallelFor(bands, [&](size_t band) {
    BandCells& grid = band_cells[band];
    const int y0 = int(band * size_t(view.height) / bands);
    const int y1 = int((band + 1) * size_t(view.height) / bands);
    size_t count = 0;
    for (int y = y0; y < y1; ++y) {
      const uint32_t* primitive = eye.primitive.row(y);
      const float* depth = eye.depth.depth.row(y);
      for (int x = 0; x < view.width; ++x) {
        if (primitive[x] == kNoPrimitive) continue;
        const dvec3 d = unproject(x, y, depth[x]) - centre;
        const double squared = glm::dot(d, d);
        if (!(squared > 0.0)) continue;
        grid.add(finestCell(d), squared, radius_per_w * near_plane / double(depth[x]));
        ++count;
      }
    }
    band_receivers[band] = count;
  });
  // A cell's farthest receiver ball reaches at most sqrt(max squared) + max radius from the
  // centre, and spans at most max radius / sqrt(min squared) (a sine) seen from it.
  farthest_.resize(size_t(levelCount()));
  spread_.resize(size_t(levelCount()));
  farthest_[0].assign(cells, -1.0f);
  spread_[0].assign(cells, 0.0f);
  for (size_t band = 0; band < bands; ++band) receivers_ += band_receivers[band];
  for (size_t c = 0; c < cells; ++c) {
    float max_squared = -1.0f, min_squared = INFINITY, max_radius = 0.0f;
    for (const BandCells& grid : band_cells) {
      max_squared = std::max(max_squared, grid.max_squared[c]);
      min_squared = std::min(min_squared, grid.min_squared[c]);
      max_radius = std::max(max_radius, grid.max_radius[c]);
    }
    if (max_squared < 0.0f) continue;  // no receiver
    const double far_side = std::sqrt(double(max_squared)) + double(max_radius);
    farthest_[0][c] = std::nextafter(float(far_side), INFINITY);
    spread_[0][c] = std::nextafter(float(double(max_radius) / std::sqrt(double(min_squared))),
                                   INFINITY);
  }
  for (int level = 1; level < levelCount(); ++level) {
    const int n = levelCells(level), fine = levelCells(level - 1);
    std::vector<float>& coarse = farthest_[size_t(level)];
    std::vector<float>& coarse_spread = spread_[size_t(level)];
    const std::vector<float>& below = farthest_[size_t(level - 1)];
    const std::vector<float>& below_spread = spread_[size_t(level - 1)];
    coarse.assign(size_t(kFaces) * n * n, -1.0f);
    coarse_spread.assign(size_t(kFaces) * n * n, 0.0f);
    for (int face = 0; face < kFaces; ++face)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          float m = -1.0f, s = 0.0f;
          for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
              const size_t k =
                  (size_t(face) * fine + size_t(2 * j + dj)) * fine + size_t(2 * i + di);
              m = std::max(m, below[k]);
              s = std::max(s, below_spread[k]);
            }
          const size_t at = (size_t(face) * n + size_t(j)) * n + size_t(i);
          coarse[at] = m;
          coarse_spread[at] = s;
        }
  }
}

bool ReceiverMask::anyFartherWithin(const dvec3& axis, double half_angle,
                                    double nearest) const {
  const int top = int(farthest_.size()) - 1;
  for (int face = 0; face < kFaces; ++face)
    if (visit(top, face, 0, 0, axis, half_angle, nearest)) return true;
  return false;
}

bool ReceiverMask::visit(int level, int face, int i, int j, const dvec3& axis,
                         double half_angle, double nearest) const {
  const int n = levelCells(level);
  const size_t at = (size_t(face) * n + size_t(j)) * n + size_t(i);
  if (!(double(farthest_[size_t(level)][at]) > nearest)) return false;
  // The cell's directions lie in the cone around its centre direction through its farthest
  // corner: the cone is convex (half-angle < 90 degrees) and holds the four corner rays, so it
  // holds the cell, their conical hull.
  const double step = 2.0 / n;
  const double s0 = -1.0 + step * i, t0 = -1.0 + step * j;
  const dvec3 cell_axis = glm::normalize(faceDirection(face, s0 + 0.5 * step, t0 + 0.5 * step));
  double cell_angle = 0.0;
  for (int corner = 0; corner < 4; ++corner) {
    const dvec3 c = glm::normalize(
        faceDirection(face, s0 + step * (corner & 1), t0 + step * (corner >> 1)));
    cell_angle = std::max(cell_angle, angleBetween(cell_axis, c));
  }
  const double ratio = double(spread_[size_t(level)][at]);
  const double spread = ratio < 1.0 ? std::asin(ratio) : std::numbers::pi;
  const double reach = half_angle + cell_angle + spread;
  if (angleBetween(axis, cell_axis) > reach) return false;
  if (level == 0) return true;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di)
      if (visit(level - 1, face, 2 * i + di, 2 * j + dj, axis, half_angle, nearest))
        return true;
  return false;
}

}  // namespace penumbra
