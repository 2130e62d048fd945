#include "raster/triangle_setup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/error.h"
#include "core/parallel.h"
#include "raster/fixed_point.h"

namespace penumbra {
namespace {

// Homogeneous clip planes, as dot(plane, clip) >= 0 inside. Near: w - z >= 0 (core/view.h);
// guard band: |x|, |y| <= g w with g chosen so the band reaches kGuardBandPixels past the edge.
struct ClipPlanes {
  double gx, gy;
  std::array<dvec4, 5> planes;
};

ClipPlanes makePlanes(int width, int height) {
  const double gx = 1.0 + 2.0 * kGuardBandPixels / width;
  const double gy = 1.0 + 2.0 * kGuardBandPixels / height;
  return {gx, gy,
          {dvec4(0, 0, -1, 1), dvec4(-1, 0, 0, gx), dvec4(1, 0, 0, gx), dvec4(0, -1, 0, gy),
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

// std::llround (halfway cases away from zero), inline: libm's is an out-of-line call and setup
// snaps two coordinates per vertex. For |v| < 2^52, v - trunc(v) is exact, so comparing it with
// +-0.5 decides exactly as llround does; anything larger (or NaN) goes to llround itself. Every
// pass snaps through this one function, which keeps a triangle drawn twice bit-identical.
inline int64_t roundHalfAwayFromZero(double v) {
  if (!(std::fabs(v) < 0x1p52)) return std::llround(v);
  int64_t i = int64_t(v);  // truncates toward zero
  const double fraction = v - double(i);
  if (fraction >= 0.5) {
    ++i;
  } else if (fraction <= -0.5) {
    --i;
  }
  return i;
}

ScreenVertex toScreen(const dvec4& c, int width, int height) {
  const double inv_w = 1.0 / c.w;
  const double sx = (c.x * inv_w * 0.5 + 0.5) * width;
  const double sy = (0.5 - c.y * inv_w * 0.5) * height;
  return {roundHalfAwayFromZero(sx * kSubpixelSteps), roundHalfAwayFromZero(sy * kSubpixelSteps),
          sx, sy, c.z * inv_w};
}

// A vertex classified once, whatever number of triangles share it. Outcode bit i: outside
// ClipPlanes::planes[i]. kNotDrawable: inside every plane yet w <= 0 (only (0, 0, z <= 0, 0)
// gets there), kNonFinite: a NaN or infinite coordinate. `screen` is set only for code 0.
constexpr uint8_t kOutsideBits = 0x1f;
constexpr uint8_t kNotDrawable = 0x40;
constexpr uint8_t kNonFinite = 0x80;

struct ClassifiedVertex {
  ScreenVertex screen;
  uint8_t code;
};

// The plane tests written out: for finite input they equal glm::dot(plane, c) >= 0 with the
// planes of makePlanes, term for term (the zero terms add +-0, which changes no comparison), so
// a triangle takes the unclipped path exactly when the clipping path would leave it whole.
ClassifiedVertex classify(const vec4& v, const ClipPlanes& planes, int width, int height) {
  ClassifiedVertex out;
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w))) {
    out.code = kNonFinite;
    return out;
  }
  const dvec4 c(v);
  const double gw_x = planes.gx * c.w, gw_y = planes.gy * c.w;
  uint8_t code = uint8_t(c.w - c.z < 0);
  code |= uint8_t(gw_x - c.x < 0) << 1;
  code |= uint8_t(gw_x + c.x < 0) << 2;
  code |= uint8_t(gw_y - c.y < 0) << 3;
  code |= uint8_t(gw_y + c.y < 0) << 4;
  if (code == 0 && !(c.w > 0)) code = kNotDrawable;
  out.code = code;
  if (code == 0) out.screen = toScreen(c, width, height);
  return out;
}

// Sets up one (already clipped) triangle; returns false when it covers no pixel.
bool setupOne(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
              int width, int height, int32_t payload, uint8_t flags, SetupTriangle& t) {
  // Twice the signed area, y pointing down: negative means counter-clockwise as seen by the
  // eye in a right-handed, y-up world, i.e. the eye sees the front face.
  const int64_t area2 = (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
  if (area2 == 0) return false;
  const int8_t facing = area2 < 0 ? 1 : -1;
  if ((flags & kCullBackFace) && facing < 0) return false;

  // Pixel box: pixel x is a candidate when its centre 16x + 8 lies within [min, max]. Tested
  // before the depth plane's divisions: most triangles that vanish do so here.
  const int64_t min_x = std::min({v0.x, v1.x, v2.x}), max_x = std::max({v0.x, v1.x, v2.x});
  const int64_t min_y = std::min({v0.y, v1.y, v2.y}), max_y = std::max({v0.y, v1.y, v2.y});
  t.min_x = int32_t(std::max<int64_t>(0, firstPixelFrom(min_x)));
  t.min_y = int32_t(std::max<int64_t>(0, firstPixelFrom(min_y)));
  t.max_x = int32_t(std::min<int64_t>(width - 1, lastPixelTo(max_x)));
  t.max_y = int32_t(std::min<int64_t>(height - 1, lastPixelTo(max_y)));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return false;

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
  t.payload = payload;
  t.facing = facing;
  t.flags = flags;
  return true;
}

// Where setupOne dropped a piece on screen (VanishedPiece), from its snapped vertices (the
// unsnapped ones lie within 1/32 pixel of them). Nothing when it lies off screen or was culled
// as a back face.
void recordVanished(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                    int width, int height, uint8_t flags, uint32_t source,
                    std::vector<VanishedPiece>* vanished) {
  if (vanished == nullptr || (flags & kCullBackFace)) return;
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  double px[3], py[3];
  for (int k = 0; k < 3; ++k) {
    px[k] = double(v[k]->x) / kSubpixelSteps;
    py[k] = double(v[k]->y) / kSubpixelSteps;
  }
  auto length2 = [&](int i, int j) {
    return (px[i] - px[j]) * (px[i] - px[j]) + (py[i] - py[j]) * (py[i] - py[j]);
  };
  int a = 0, b = 1;
  if (length2(1, 2) > length2(a, b)) a = 1, b = 2;
  if (length2(0, 2) > length2(a, b)) a = 0, b = 2;
  const int c = 3 - a - b;
  // The third vertex's distance from segment a-b (from a when a and b coincide).
  const double dx = px[b] - px[a], dy = py[b] - py[a], ab2 = dx * dx + dy * dy;
  const double t =
      ab2 > 0.0 ? std::clamp(((px[c] - px[a]) * dx + (py[c] - py[a]) * dy) / ab2, 0.0, 1.0) : 0.0;
  const double off_x = px[a] + t * dx - px[c], off_y = py[a] + t * dy - py[c];
  const double slack = 1.0 + std::sqrt(off_x * off_x + off_y * off_y);
  // Pixels x with x + 0.5 within `slack` of the vertices' box, clamped to the image.
  auto first = [&](double lo) { return std::max(0.0, std::ceil(lo - slack - 0.5)); };
  auto last = [&](double hi, int size) {
    return std::min(double(size - 1), std::floor(hi + slack - 0.5));
  };
  const double x0 = first(std::min({px[0], px[1], px[2]}));
  const double y0 = first(std::min({py[0], py[1], py[2]}));
  const double x1 = last(std::max({px[0], px[1], px[2]}), width);
  const double y1 = last(std::max({py[0], py[1], py[2]}), height);
  if (!(x0 <= x1 && y0 <= y1)) return;
  // The third vertex's depth against the segment's at its projection onto it: depth (1 / w) is
  // affine in screen space, so a point of the piece, a mix of the three vertices, lies within
  // that much of the segment's depth where it projects.
  const double spread = std::fabs(v[c]->depth - (v[a]->depth + t * (v[b]->depth - v[a]->depth)));
  vanished->push_back({source, px[a], py[a], px[b], py[b], slack, int32_t(x0), int32_t(y0),
                       int32_t(x1), int32_t(y1), v[a]->depth, v[b]->depth, spread});
}

SetupTriangle& withOwners(const ClipTriangles& tris, size_t t, SetupTriangle& s) {
  if (!tris.owners.empty()) {
    s.owners[0] = tris.owners[2 * t];
    s.owners[1] = tris.owners[2 * t + 1];
  }
  return s;
}

// Triangles with a vertex outside some plane: clipped in double from the original clip-space
// vertices, then fanned from the first remaining vertex.
void setupClipped(const ClipTriangles& tris, size_t t, const ClipPlanes& planes, int width,
                  int height, uint8_t flags, std::vector<SetupTriangle>& out,
                  std::vector<VanishedPiece>* vanished) {
  std::array<dvec4, 8> poly;
  for (int k = 0; k < 3; ++k) poly[k] = dvec4(tris.vertex(tris.indices[t * 3 + k]));
  const int count = clipPolygon(poly, 3, planes);
  if (count < 3) return;
  std::array<ScreenVertex, 8> screen;
  for (int k = 0; k < count; ++k) {
    if (!(poly[k].w > 0)) return;  // only a degenerate triangle on the eye plane gets here
    screen[k] = toScreen(poly[k], width, height);
  }
  for (int k = 1; k + 1 < count; ++k) {
    SetupTriangle s;
    if (setupOne(screen[0], screen[k], screen[k + 1], width, height, tris.payload[t], flags, s))
      out.push_back(withOwners(tris, t, s));
    else
      recordVanished(screen[0], screen[k], screen[k + 1], width, height, flags, uint32_t(t),
                     vanished);
  }
}

// `vertex(i)` returns the ClassifiedVertex of clip vertex i, precomputed or computed on demand:
// the result is the same either way.
template <class VertexFn>
void setupRange(const ClipTriangles& tris, size_t begin, size_t end, int width, int height,
                const ClipPlanes& planes, const VertexFn& vertex, std::vector<SetupTriangle>& out,
                std::vector<uint32_t>* sources, std::vector<VanishedPiece>* vanished) {
  // Sets up input triangle t into `out` (none, one, or a clipped fan of pieces).
  const auto setupInput = [&](size_t t) {
    const uint8_t flags = tris.flags.empty() ? 0 : tris.flags[t];
    const uint32_t* idx = &tris.indices[t * 3];
    const ClassifiedVertex& c0 = vertex(idx[0]);
    const ClassifiedVertex& c1 = vertex(idx[1]);
    const ClassifiedVertex& c2 = vertex(idx[2]);
    const uint8_t any = c0.code | c1.code | c2.code;
    if (any == 0) {
      SetupTriangle s;
      if (setupOne(c0.screen, c1.screen, c2.screen, width, height, tris.payload[t], flags, s))
        out.push_back(withOwners(tris, t, s));
      else
        recordVanished(c0.screen, c1.screen, c2.screen, width, height, flags, uint32_t(t),
                       vanished);
      return;
    }
    // NaN or infinite input covers nothing, and must not crash.
    if (any & kNonFinite) return;
    // Inside every plane but on the eye plane (w = 0): nothing to draw, as with clipping.
    if ((any & kOutsideBits) == 0) return;
    // All three outside one plane: so is the whole triangle (trivial reject).
    if (c0.code & c1.code & c2.code & kOutsideBits) return;
    setupClipped(tris, t, planes, width, height, flags, out, vanished);
  };
  for (size_t t = begin; t < end; ++t) {
    setupInput(t);
    if (sources != nullptr) sources->resize(out.size(), uint32_t(t));  // t's pieces
  }
}

}  // namespace

std::vector<SetupTriangle> setupTriangles(const ClipTriangles& tris, int width, int height,
                                          std::vector<uint32_t>* sources,
                                          std::vector<VanishedPiece>* vanished) {
  PENUMBRA_CHECK(width > 0 && height > 0 && width <= kMaxImageSize && height <= kMaxImageSize,
                 "image size {}x{} is outside 1..{}", width, height, kMaxImageSize);
  PENUMBRA_DCHECK(tris.indices.size() == tris.payload.size() * 3);
  PENUMBRA_DCHECK(tris.owners.empty() || tris.owners.size() == tris.payload.size() * 2);
  const ClipPlanes planes = makePlanes(width, height);
  // Chunks of at most 4096 triangles (or vertices), and at least four per worker down to 256,
  // so that a scene of a few thousand triangles and a volume of a few hundred quads still keep
  // every worker busy. The parts are joined in chunk order: the result does not depend on it.
  const size_t per_worker = 4 * size_t(std::max(1, workerCount()));
  auto chunkFor = [&](size_t items) { return std::clamp<size_t>(items / per_worker, 256, 4096); };

  // Classify each vertex once when vertices are shared (a mesh's vertex belongs to ~6
  // triangles); when most vertices are unused (shadow volumes: only silhouette vertices and
  // caps), classify the three corners of each triangle instead. Same results either way.
  const size_t vertex_count = tris.vertexCount();
  const bool per_vertex = tris.indices.size() >= vertex_count;
  std::unique_ptr<ClassifiedVertex[]> classified;
  if (per_vertex) {
    classified.reset(new ClassifiedVertex[vertex_count]);
    const size_t vertex_chunk = chunkFor(vertex_count);
    parallelFor((vertex_count + vertex_chunk - 1) / vertex_chunk, [&](size_t c) {
      const size_t begin = c * vertex_chunk, end = std::min(vertex_count, begin + vertex_chunk);
      for (size_t i = begin; i < end; ++i)
        classified[i] = classify(tris.vertex(uint32_t(i)), planes, width, height);
    });
  }

  const size_t triangle_chunk = chunkFor(tris.size());
  const size_t chunks = (tris.size() + triangle_chunk - 1) / triangle_chunk;
  std::vector<std::vector<SetupTriangle>> parts(chunks);
  std::vector<std::vector<uint32_t>> part_sources(sources != nullptr ? chunks : 0);
  std::vector<std::vector<VanishedPiece>> part_vanished(vanished != nullptr ? chunks : 0);
  parallelFor(chunks, [&](size_t c) {
    const size_t begin = c * triangle_chunk, end = std::min(tris.size(), begin + triangle_chunk);
    parts[c].reserve(end - begin);
    if (per_vertex) {
      const ClassifiedVertex* table = classified.get();
      setupRange(tris, begin, end, width, height, planes,
                 [table](uint32_t i) -> const ClassifiedVertex& { return table[i]; }, parts[c],
                 sources != nullptr ? &part_sources[c] : nullptr,
                 vanished != nullptr ? &part_vanished[c] : nullptr);
    } else {
      setupRange(tris, begin, end, width, height, planes,
                 [&](uint32_t i) { return classify(tris.vertex(i), planes, width, height); },
                 parts[c], sources != nullptr ? &part_sources[c] : nullptr,
                 vanished != nullptr ? &part_vanished[c] : nullptr);
    }
  });
  size_t total = 0;
  for (const auto& p : parts) total += p.size();
  std::vector<SetupTriangle> out;
  out.reserve(total);
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  if (sources != nullptr) {
    sources->clear();
    sources->reserve(total);
    for (const auto& p : part_sources) sources->insert(sources->end(), p.begin(), p.end());
  }
  if (vanished != nullptr) {
    vanished->clear();
    for (const auto& p : part_vanished) vanished->insert(vanished->end(), p.begin(), p.end());
  }
  return out;
}

}  // namespace penumbra
