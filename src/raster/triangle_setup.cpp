#include "raster/triangle_setup.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"
#include "raster/fixed_point.h"

namespace penumbra {
namespace {

// Homogeneous clip planes, as dot(plane, clip) >= 0 inside. Near: w - z >= 0 (core/view.h);
// guard band: |x|, |y| <= g w with g chosen so the band reaches kGuardBandPixels past the edge.
struct ClipPlanes {
  std::array<dvec4, 5> planes;
};

ClipPlanes makePlanes(int width, int height) {
  const double gx = 1.0 + 2.0 * kGuardBandPixels / width;
  const double gy = 1.0 + 2.0 * kGuardBandPixels / height;
  return {{dvec4(0, 0, -1, 1), dvec4(-1, 0, 0, gx), dvec4(1, 0, 0, gx), dvec4(0, -1, 0, gy),
           dvec4(0, 1, 0, gy)}};
}

bool lexicographicLess(const dvec4& p, const dvec4& q) {
  for (int i = 0; i < 4; ++i) {
    if (p[i] != q[i]) return p[i] < q[i];
  }
  return false;
}

// Intersection of segment (p, q) with a plane, computed from the lexicographically smaller
// endpoint so both triangles sharing the segment get the bit-identical point (a shared edge
// must stay shared after clipping, or the watertight guarantee breaks).
dvec4 intersect(const dvec4& p, double dp, const dvec4& q, double dq) {
  if (lexicographicLess(q, p)) return intersect(q, dq, p, dp);
  const double t = dp / (dp - dq);
  return p + (q - p) * t;
}

// Sutherland-Hodgman against the planes some vertex violates. At most 3 + 5 vertices result.
int clipPolygon(std::array<dvec4, 8>& poly, int count, const ClipPlanes& clip_planes) {
  std::array<dvec4, 8> out;
  for (const dvec4& plane : clip_planes.planes) {
    std::array<double, 8> dist;
    bool any_out = false;
    bool all_out = true;
    for (int i = 0; i < count; ++i) {
      dist[i] = glm::dot(plane, poly[i]);
      any_out |= dist[i] < 0;
      all_out &= dist[i] < 0;
    }
    if (all_out) return 0;
    if (!any_out) continue;
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const int j = (i + 1) % count;
      if (dist[i] >= 0) out[n++] = poly[i];
      if ((dist[i] >= 0) != (dist[j] >= 0)) out[n++] = intersect(poly[i], dist[i], poly[j], dist[j]);
    }
    count = n;
    poly = out;
    if (count < 3) return 0;
  }
  return count;
}

struct ScreenVertex {
  int64_t x, y;     // 28.4, snapped: coverage
  double sx, sy;    // pixels, unsnapped: depth plane
  double depth;     // reversed-Z
};

// Sets up one (already clipped) triangle; returns false when it covers no pixel.
bool setupOne(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
              int width, int height, int32_t payload, uint8_t flags, SetupTriangle& t) {
  // Twice the signed area, y pointing down: negative means counter-clockwise as seen by the
  // eye in a right-handed, y-up world, i.e. the eye sees the front face.
  const int64_t area2 = (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
  if (area2 == 0) return false;
  const int8_t facing = area2 < 0 ? 1 : -1;
  if ((flags & kCullBackFace) && facing < 0) return false;

  // Depth plane from the unsnapped vertices, in input order (see SetupTriangle::a). Snapped
  // vertices would tilt small triangles' planes by up to 1/32 pixel over their size: enough to
  // reorder a surface and the shadow-volume quad grazing it near the light's terminator.
  {
    const double x1 = v1.sx - v0.sx, y1 = v1.sy - v0.sy;
    const double x2 = v2.sx - v0.sx, y2 = v2.sy - v0.sy;
    const double d1 = v1.depth - v0.depth, d2 = v2.depth - v0.depth;
    const double det = x1 * y2 - x2 * y1;
    if (det == 0.0) return false;  // covers pixels only through snapping: no plane to give
    t.a = (d1 * y2 - d2 * y1) / det;
    t.b = (x1 * d2 - x2 * d1) / det;
    t.c = v0.depth - t.a * v0.sx - t.b * v0.sy;
  }
  t.depth_min = float(std::min({v0.depth, v1.depth, v2.depth}));
  t.depth_max = float(std::max({v0.depth, v1.depth, v2.depth}));

  // Edge functions need positive area: walk the vertices so that area2 > 0.
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  if (area2 < 0) std::swap(v[1], v[2]);
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& p = *v[i];
    const ScreenVertex& q = *v[(i + 1) % 3];
    const int64_t A = p.y - q.y;
    const int64_t B = q.x - p.x;
    // Top-left rule with y down: the interior lies along the gradient (A, B). A left edge has
    // the interior to its right (A > 0); a top edge is horizontal with the interior below
    // (A == 0, B > 0). Other edges exclude pixel centres lying exactly on them.
    const bool top_left = A > 0 || (A == 0 && B > 0);
    t.A[i] = int32_t(A);
    t.B[i] = int32_t(B);
    t.C[i] = -(A * p.x + B * p.y) - (top_left ? 0 : 1);
  }

  // Pixel box: pixel x is a candidate when its centre 16x + 8 lies within [min, max].
  const int64_t min_x = std::min({v0.x, v1.x, v2.x}), max_x = std::max({v0.x, v1.x, v2.x});
  const int64_t min_y = std::min({v0.y, v1.y, v2.y}), max_y = std::max({v0.y, v1.y, v2.y});
  auto ceil_div = [](int64_t a, int64_t b) { return a >= 0 ? (a + b - 1) / b : -((-a) / b); };
  auto floor_div = [](int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  const int64_t half = kSubpixelSteps / 2;
  t.min_x = int32_t(std::max<int64_t>(0, ceil_div(min_x - half, kSubpixelSteps)));
  t.min_y = int32_t(std::max<int64_t>(0, ceil_div(min_y - half, kSubpixelSteps)));
  t.max_x = int32_t(std::min<int64_t>(width - 1, floor_div(max_x - half, kSubpixelSteps)));
  t.max_y = int32_t(std::min<int64_t>(height - 1, floor_div(max_y - half, kSubpixelSteps)));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return false;
  t.payload = payload;
  t.facing = facing;
  t.flags = flags;
  return true;
}

ScreenVertex toScreen(const dvec4& c, int width, int height) {
  const double inv_w = 1.0 / c.w;
  const double sx = (c.x * inv_w * 0.5 + 0.5) * width;
  const double sy = (0.5 - c.y * inv_w * 0.5) * height;
  return {std::llround(sx * kSubpixelSteps), std::llround(sy * kSubpixelSteps), sx, sy, c.z * inv_w};
}

void setupRange(const ClipTriangles& tris, size_t begin, size_t end, int width, int height,
                const ClipPlanes& planes, std::vector<SetupTriangle>& out) {
  for (size_t t = begin; t < end; ++t) {
    const uint8_t flags = tris.flags.empty() ? 0 : tris.flags[t];
    std::array<dvec4, 8> poly;
    bool inside_all = true;
    bool finite_input = true;
    for (int k = 0; k < 3; ++k) {
      poly[k] = dvec4(tris.clip[tris.indices[t * 3 + k]]);
      for (int c = 0; c < 4; ++c) finite_input &= std::isfinite(poly[k][c]);
      for (const dvec4& plane : planes.planes) inside_all &= glm::dot(plane, poly[k]) >= 0;
    }
    if (!finite_input) continue;  // NaN or infinite input covers nothing, and must not crash
    const int count = inside_all ? 3 : clipPolygon(poly, 3, planes);
    if (count < 3) continue;
    std::array<ScreenVertex, 8> screen;
    bool finite = true;
    for (int k = 0; k < count; ++k) {
      finite &= poly[k].w > 0;
      screen[k] = toScreen(poly[k], width, height);
    }
    if (!finite) continue;  // only a degenerate triangle on the eye plane gets here
    for (int k = 1; k + 1 < count; ++k) {
      SetupTriangle s;
      if (setupOne(screen[0], screen[k], screen[k + 1], width, height, tris.payload[t], flags, s))
        out.push_back(s);
    }
  }
}

}  // namespace

std::vector<SetupTriangle> setupTriangles(const ClipTriangles& tris, int width, int height) {
  PENUMBRA_CHECK(width > 0 && height > 0 && width <= kMaxImageSize && height <= kMaxImageSize,
                 "image size {}x{} is outside 1..{}", width, height, kMaxImageSize);
  PENUMBRA_DCHECK(tris.indices.size() == tris.payload.size() * 3);
  const ClipPlanes planes = makePlanes(width, height);
  constexpr size_t kChunk = 4096;
  const size_t chunks = (tris.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<SetupTriangle>> parts(chunks);
  parallelFor(chunks, [&](size_t c) {
    const size_t begin = c * kChunk, end = std::min(tris.size(), begin + kChunk);
    parts[c].reserve(end - begin);
    setupRange(tris, begin, end, width, height, planes, parts[c]);
  });
  size_t total = 0;
  for (const auto& p : parts) total += p.size();
  std::vector<SetupTriangle> out;
  out.reserve(total);
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace penumbra
