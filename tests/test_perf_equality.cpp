// The performance rewrites must not change results: triangle setup (per-vertex classification,
// inline rounding, trivial reject) against the straightforward per-triangle setup it replaced,
// the tile z-min/z-max pyramid against a brute-force one, shading into a reused image against a
// fresh one, and the optimised shading against the per-pixel formulas it replaced.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/parallel.h"
#include "raster/depth_buffer.h"
#include "raster/fixed_point.h"
#include "raster/triangle_setup.h"
#include "raster_test_util.h"
#include "render/frame.h"
#include "render/shading.h"
#include "render/shading_reuse.h"
#include "scene/builtin_scenes.h"

namespace penumbra {
namespace test_perf_equality {

using testing::screenToClip;
using testing::TestRandom;

// The setup as it was before the per-vertex rewrite: every triangle converts, tests and snaps
// its three corners itself (std::llround) and clips whenever a corner is outside some plane.
namespace reference {

std::array<dvec4, 5> planes(int width, int height) {
  const double gx = 1.0 + 2.0 * kGuardBandPixels / width;
  const double gy = 1.0 + 2.0 * kGuardBandPixels / height;
  return {dvec4(0, 0, -1, 1), dvec4(-1, 0, 0, gx), dvec4(1, 0, 0, gx), dvec4(0, -1, 0, gy),
          dvec4(0, 1, 0, gy)};
}

dvec4 intersect(const dvec4& p, double dp, const dvec4& q, double dq) {
  for (int i = 0; i < 4; ++i) {
    if (p[i] != q[i]) {
      if (q[i] < p[i]) return intersect(q, dq, p, dp);
      break;
    }
  }
  const double t = dp / (dp - dq);
  return p + (q - p) * t;
}

int clipPolygon(std::array<dvec4, 8>& poly, int count, const std::array<dvec4, 5>& clip_planes) {
  std::array<dvec4, 8> out;
  for (const dvec4& plane : clip_planes) {
    std::array<double, 8> dist;
    bool any_out = false, all_out = true;
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
      if ((dist[i] >= 0) != (dist[j] >= 0))
        out[n++] = intersect(poly[i], dist[i], poly[j], dist[j]);
    }
    count = n;
    poly = out;
    if (count < 3) return 0;
  }
  return count;
}

struct ScreenVertex {
  int64_t x, y;
  double sx, sy, depth;
};

bool setupOne(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int width,
              int height, int32_t payload, uint8_t flags, SetupTriangle& t) {
  const int64_t area2 = (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
  if (area2 == 0) return false;
  const int8_t facing = area2 < 0 ? 1 : -1;
  if ((flags & kCullBackFace) && facing < 0) return false;
  const double x1 = v1.sx - v0.sx, y1 = v1.sy - v0.sy;
  const double x2 = v2.sx - v0.sx, y2 = v2.sy - v0.sy;
  const double d1 = v1.depth - v0.depth, d2 = v2.depth - v0.depth;
  const double det = x1 * y2 - x2 * y1;
  if (det == 0.0) return false;
  t.a = (d1 * y2 - d2 * y1) / det;
  t.b = (x1 * d2 - x2 * d1) / det;
  t.c = v0.depth - t.a * v0.sx - t.b * v0.sy;
  t.depth_min = float(std::min({v0.depth, v1.depth, v2.depth}));
  t.depth_max = float(std::max({v0.depth, v1.depth, v2.depth}));
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  if (area2 < 0) std::swap(v[1], v[2]);
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& p = *v[i];
    const ScreenVertex& q = *v[(i + 1) % 3];
    const int64_t A = p.y - q.y, B = q.x - p.x;
    const bool top_left = A > 0 || (A == 0 && B > 0);
    t.A[i] = int32_t(A);
    t.B[i] = int32_t(B);
    t.C[i] = -(A * p.x + B * p.y) - (top_left ? 0 : 1);
  }
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
  return {std::llround(sx * kSubpixelSteps), std::llround(sy * kSubpixelSteps), sx, sy,
          c.z * inv_w};
}

std::vector<SetupTriangle> setupTriangles(const ClipTriangles& tris, int width, int height) {
  const std::array<dvec4, 5> clip_planes = planes(width, height);
  std::vector<SetupTriangle> out;
  for (size_t t = 0; t < tris.size(); ++t) {
    const uint8_t flags = tris.flags.empty() ? 0 : tris.flags[t];
    std::array<dvec4, 8> poly;
    bool inside_all = true, finite_input = true;
    for (int k = 0; k < 3; ++k) {
      poly[k] = dvec4(tris.clip[tris.indices[t * 3 + k]]);
      for (int c = 0; c < 4; ++c) finite_input &= std::isfinite(poly[k][c]);
      for (const dvec4& plane : clip_planes) inside_all &= glm::dot(plane, poly[k]) >= 0;
    }
    if (!finite_input) continue;
    const int count = inside_all ? 3 : clipPolygon(poly, 3, clip_planes);
    if (count < 3) continue;
    std::array<ScreenVertex, 8> screen;
    bool finite = true;
    for (int k = 0; k < count; ++k) {
      finite &= poly[k].w > 0;
      screen[k] = toScreen(poly[k], width, height);
    }
    if (!finite) continue;
    for (int k = 1; k + 1 < count; ++k) {
      SetupTriangle s;
      if (setupOne(screen[0], screen[k], screen[k + 1], width, height, tris.payload[t], flags, s))
        out.push_back(s);
    }
  }
  return out;
}

}  // namespace reference

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Field by field (the struct has padding), doubles and floats bit for bit.
void expectSameSetup(const std::vector<SetupTriangle>& got, const std::vector<SetupTriangle>& want,
                     const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (size_t i = 0; i < got.size(); ++i) {
    const SetupTriangle &g = got[i], &w = want[i];
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(g.A[k], w.A[k]) << what << " triangle " << i;
      ASSERT_EQ(g.B[k], w.B[k]) << what << " triangle " << i;
      ASSERT_EQ(g.C[k], w.C[k]) << what << " triangle " << i;
    }
    ASSERT_TRUE(sameBits(g.a, w.a) && sameBits(g.b, w.b) && sameBits(g.c, w.c))
        << what << " triangle " << i;
    ASSERT_TRUE(sameBits(g.depth_min, w.depth_min) && sameBits(g.depth_max, w.depth_max))
        << what << " triangle " << i;
    ASSERT_EQ(g.min_x, w.min_x) << what << " triangle " << i;
    ASSERT_EQ(g.min_y, w.min_y) << what << " triangle " << i;
    ASSERT_EQ(g.max_x, w.max_x) << what << " triangle " << i;
    ASSERT_EQ(g.max_y, w.max_y) << what << " triangle " << i;
    ASSERT_EQ(g.payload, w.payload) << what << " triangle " << i;
    ASSERT_EQ(g.facing, w.facing) << what << " triangle " << i;
    ASSERT_EQ(g.flags, w.flags) << what << " triangle " << i;
  }
}

// A jittered grid mesh in clip space whose vertices are shared by up to six triangles, spread
// well past the guard band and through the near plane (w from -0.5 to 3), plus points at
// infinity (w = 0, z = 0) as shadow volumes make them, so every path of the setup is taken.
ClipTriangles gridSoup(int width, int height, uint64_t seed, int n) {
  TestRandom rng(seed);
  ClipTriangles tris;
  const double reach = 1.0 + 4.0 * kGuardBandPixels / std::min(width, height);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double w = rng.uniform() < 0.1 ? 0.0 : rng.uniform(-0.5, 3.0);
      const double scale = rng.uniform() < 0.2 ? reach : 1.3;
      const double x = (2.0 * i / n - 1.0 + rng.uniform(-0.3, 0.3) / n) * scale * std::abs(w);
      const double y = (2.0 * j / n - 1.0 + rng.uniform(-0.3, 0.3) / n) * scale * std::abs(w);
      const double near = 0.05;
      const double z = w == 0.0 ? 0.0 : near * (rng.uniform() < 0.9 ? 1.0 : -1.0);
      const double w_stored = w == 0.0 ? rng.uniform(0, 1e-3) : w;
      tris.clip.emplace_back(float(x), float(y), float(z), float(w_stored));
    }
  uint32_t id = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      const uint8_t flags = rng.uniform() < 0.3 ? kCullBackFace : 0;
      tris.add(a, b, d, int32_t(id++), flags);
      tris.add(a, d, c, int32_t(id++), uint8_t(flags | kZFail));
    }
  return tris;
}

TEST(PerfEquality, SetupMatchesPerTriangleReferenceOnSharedVertices) {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const int width = 131 + int(seed) * 17, height = 97 + int(seed) * 5;
    const ClipTriangles tris = gridSoup(width, height, seed, 70);
    ASSERT_GE(tris.indices.size(), tris.clip.size());  // per-vertex classification
    expectSameSetup(setupTriangles(tris, width, height),
                    reference::setupTriangles(tris, width, height), "grid");
  }
}

// Shadow volumes reference few of their vertices: setup classifies per triangle corner then,
// and must give the same triangles as per vertex.
TEST(PerfEquality, SetupPerCornerEqualsPerVertex) {
  const int width = 160, height = 120;
  ClipTriangles tris = gridSoup(width, height, 11, 40);
  const std::vector<SetupTriangle> per_vertex = setupTriangles(tris, width, height);
  const size_t used = tris.clip.size();
  tris.clip.resize(tris.indices.size() + used + 1, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  ASSERT_LT(tris.indices.size(), tris.clip.size());
  const std::vector<SetupTriangle> per_corner = setupTriangles(tris, width, height);
  expectSameSetup(per_corner, per_vertex, "per corner");
  expectSameSetup(per_corner, reference::setupTriangles(tris, width, height), "reference");
}

// Snapping halfway cases: vertices exactly on odd multiples of 1/32 pixel round away from zero,
// as std::llround does, also for the negative coordinates of the guard band.
TEST(PerfEquality, SetupRoundsHalfwayCasesLikeLlround) {
  const int width = 64, height = 64;
  ClipTriangles tris;
  TestRandom rng(5);
  for (int t = 0; t < 2000; ++t) {
    for (int k = 0; k < 3; ++k) {
      // sx = m / 32 pixels: sx * 16 = m / 2, a halfway case for odd m; x = 2 sx / 64 - 1 exact.
      const double mx = std::floor(rng.uniform(-40 * 32, 104 * 32));
      const double my = std::floor(rng.uniform(-40 * 32, 104 * 32));
      tris.clip.push_back(screenToClip(mx / 32.0, my / 32.0, rng.uniform(0.1, 1.0), width, height));
    }
    tris.add(uint32_t(t * 3), uint32_t(t * 3 + 1), uint32_t(t * 3 + 2), t);
  }
  const std::vector<SetupTriangle> got = setupTriangles(tris, width, height);
  EXPECT_GT(got.size(), 1000u);
  expectSameSetup(got, reference::setupTriangles(tris, width, height), "halfway");
}

TEST(PerfEquality, SetupDropsNonFiniteAndEyePlaneTrianglesLikeReference) {
  const int width = 40, height = 30;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  ClipTriangles tris;
  tris.clip = {vec4(nan, 0, 0.5f, 1), vec4(0.5f, 0, 0.5f, 1), vec4(0, 0.5f, 0.5f, 1),
               vec4(0, 0, inf, 1),    vec4(0, 0, 0, 0),       vec4(0, 0, -1, 0),
               vec4(-1, -1, 0.5f, 1), vec4(3, -1, 0.5f, 1),   vec4(-1, 3, 0.5f, 1)};
  for (uint32_t a = 0; a < 9; ++a)
    for (uint32_t b = 0; b < 9; ++b)
      for (uint32_t c = 0; c < 9; ++c) tris.add(a, b, c, int32_t(a * 81 + b * 9 + c));
  expectSameSetup(setupTriangles(tris, width, height),
                  reference::setupTriangles(tris, width, height), "degenerate");
}

// Brute force: every tile's min and max over its pixels inside the image.
void expectPyramid(const DepthBuffer& buffer) {
  const int w = buffer.width(), h = buffer.height();
  for (int level = kMinTileLevel; level <= kMaxTileLevel; ++level) {
    const TileDepthRange& r = buffer.tileRange(level);
    const int size = 1 << level;
    ASSERT_EQ(r.zmin.width(), (w + size - 1) / size);
    ASSERT_EQ(r.zmin.height(), (h + size - 1) / size);
    for (int ty = 0; ty < r.zmin.height(); ++ty)
      for (int tx = 0; tx < r.zmin.width(); ++tx) {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (int y = ty * size; y < std::min(h, (ty + 1) * size); ++y)
          for (int x = tx * size; x < std::min(w, (tx + 1) * size); ++x) {
            lo = std::min(lo, buffer.depth.at(x, y));
            hi = std::max(hi, buffer.depth.at(x, y));
          }
        ASSERT_EQ(r.zmin.at(tx, ty), lo) << w << "x" << h << " level " << level;
        ASSERT_EQ(r.zmax.at(tx, ty), hi) << w << "x" << h << " level " << level;
      }
  }
}

TEST(PerfEquality, TilePyramidMatchesBruteForce) {
  TestRandom rng(3);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{
           {1, 1}, {2, 2}, {3, 1}, {1, 300}, {300, 1}, {203, 117}, {257, 513}, {640, 427}}) {
    DepthBuffer buffer;
    buffer.depth.resize(w, h, 0.0f);
    for (size_t i = 0; i < buffer.depth.size(); ++i)
      buffer.depth[i] = rng.uniform() < 0.2 ? 0.0f : float(rng.uniform(0.0, 1.0));
    buffer.buildTileRanges();
    expectPyramid(buffer);
    // Rebuilding after the depth changed (a reused buffer) replaces every level.
    for (size_t i = 0; i < buffer.depth.size(); ++i) buffer.depth[i] *= 0.5f;
    buffer.buildTileRanges();
    expectPyramid(buffer);
  }
}

// The shading of the lead's per-pixel formulation (one normalisation per vector, std::pow),
// kept here to show the cheaper arithmetic changes colours by float rounding only.
vec3 referenceShade(const Scene& scene, const View& view, const EyeBuffers& eye,
                    const std::vector<const Image<float>*>& visibility, int x, int y) {
  const uint32_t id = eye.primitive.at(x, y);
  const float depth = eye.depth.depth.at(x, y);
  if (id == kNoPrimitive || !(depth > 0.0f)) return scene.settings.background;
  const auto [mesh_index, triangle] = scene.locateTriangle(id);
  const Mesh& mesh = scene.meshes[mesh_index];
  const vec3 a = mesh.vertex(triangle, 0), e0 = mesh.vertex(triangle, 1) - a,
             e1 = mesh.vertex(triangle, 2) - a;
  const dvec3 p64 = view.unproject(x, y, depth);
  const vec3 p(p64);
  const vec3 to_eye = view.eye - p;
  const vec3 geometric = glm::normalize(glm::cross(e0, e1));
  vec3 n = geometric;
  if (mesh.corner_normals.size() == mesh.indices.size()) {
    const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const float denominator = d00 * d11 - d01 * d01;
    const vec3 ep = p - a;
    const float dp0 = glm::dot(ep, e0), dp1 = glm::dot(ep, e1);
    const float v = std::max(0.0f, (d11 * dp0 - d01 * dp1) / denominator);
    const float w = std::max(0.0f, (d00 * dp1 - d01 * dp0) / denominator);
    const float u = std::max(0.0f, 1.0f - (d11 * dp0 - d01 * dp1) / denominator -
                                       (d00 * dp1 - d01 * dp0) / denominator);
    const vec3* c = &mesh.corner_normals[size_t(triangle) * 3];
    n = glm::normalize((u * c[0] + v * c[1] + w * c[2]) / (u + v + w));
  }
  if (glm::dot(geometric, to_eye) < 0.0f) n = -n;
  const Material& m = scene.materials[mesh.material];
  const vec3 v = glm::normalize(to_eye);
  vec3 color(0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const float vis = visibility[i] ? visibility[i]->at(x, y) : 1.0f;
    if (!(vis > 0.0f)) continue;
    const vec3 l = glm::normalize(light.center - p);
    const float n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0f) continue;
    vec3 reflected = m.albedo * n_dot_l;
    if (m.specular != vec3(0.0f))
      reflected += m.specular * std::pow(std::max(0.0f, glm::dot(n, glm::normalize(l + v))),
                                         m.shininess);
    color += reflected * light.color * light.intensity * std::min(vis, 1.0f);
  }
  return color + scene.settings.ambient * m.albedo;
}

TEST(PerfEquality, ShadingMatchesPerPixelFormulasAndReusedImage) {
  for (const char* name : {"spheres", "columns"}) {
    const Scene scene = builtinScene(name);
    FrameOptions options;
    options.width = 160;
    options.height = 107;
    const FrameResult frame = renderFrame(scene, options);
    std::vector<const Image<float>*> visibility;
    for (const TechniqueResult& r : frame.lights) visibility.push_back(&r.visibility);
    const Image<vec3> fresh = shadeFrame(scene, frame.view, frame.eye, visibility);
    EXPECT_TRUE(fresh == frame.color) << name;
    Image<vec3> reused(options.width, options.height, vec3(-1.0f));
    shadeFrameInto(scene, frame.view, frame.eye, visibility, reused);
    EXPECT_TRUE(reused == fresh) << name;
    double worst = 0.0;
    for (int y = 0; y < options.height; ++y)
      for (int x = 0; x < options.width; ++x) {
        const vec3 want = referenceShade(scene, frame.view, frame.eye, visibility, x, y);
        const vec3 got = fresh.at(x, y);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(got[c] - want[c])));
      }
    // Float rounding of a different but equivalent evaluation order, and the unprojection
    // done in float from an incremental ray: far below one 8-bit PNG step (1/255 ~ 4e-3).
    EXPECT_LT(worst, 2e-4) << name;
  }
}

// The SIMD shading kernel and its scalar twin agree bit for bit, on scenes with several lights,
// partial visibility, a non-integer Blinn-Phong exponent, background and odd row lengths.
TEST(PerfEquality, ShadingSimdAndScalarTwinsAreIdentical) {
  for (const char* name : {"spheres", "columns", "multilight", "year2002"}) {
    Scene scene = builtinScene(name);
    if (scene.materials.size() > 1) scene.materials[1].shininess = 10.5f;
    FrameOptions options;
    options.width = 203;
    options.height = 117;
    const FrameResult frame = renderFrame(scene, options);
    std::vector<Image<float>> partial;
    for (size_t i = 0; i < frame.lights.size(); ++i) {
      Image<float> v = frame.lights[i].visibility;
      for (size_t p = 0; p < v.size(); ++p)
        if (p % 7 == i % 7) v[p] = 0.3f;
      partial.push_back(std::move(v));
    }
    std::vector<const Image<float>*> visibility;
    for (size_t i = 0; i < partial.size(); ++i)
      visibility.push_back(i == 1 ? nullptr : &partial[i]);
    Image<vec3> simd, scalar;
    shadeFrameInto(scene, frame.view, frame.eye, visibility, simd, true);
    shadeFrameInto(scene, frame.view, frame.eye, visibility, scalar, false);
    ASSERT_EQ(simd.size(), scalar.size());
    EXPECT_EQ(std::memcmp(simd.data(), scalar.data(), simd.size() * sizeof(vec3)), 0) << name;
  }
}

// A FrameRenderer rendering into a reused FrameResult gives the frame a fresh one does, also
// after the size changed in between.
TEST(PerfEquality, RenderFrameReuseEqualsFresh) {
  const Scene scene = builtinScene("spheres");
  FrameResult reused;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{96, 64}, {120, 80}, {120, 80}}) {
    FrameOptions options;
    options.width = w;
    options.height = h;
    FrameRenderer(scene, options).render(reused);
    const FrameResult fresh = renderFrame(scene, options);
    EXPECT_TRUE(reused.color == fresh.color) << w << "x" << h;
    EXPECT_TRUE(reused.eye.depth.depth == fresh.eye.depth.depth);
    ASSERT_EQ(reused.lights.size(), fresh.lights.size());
    for (size_t i = 0; i < fresh.lights.size(); ++i)
      EXPECT_TRUE(reused.lights[i].visibility == fresh.lights[i].visibility);
    EXPECT_TRUE(reused.total.sameCounters(fresh.total));
    // The one-off frame also times preparing the technique for the scene, first.
    ASSERT_EQ(reused.total.time_ms.size() + 1, fresh.total.time_ms.size());
    EXPECT_EQ(fresh.total.time_ms.front().first, "prepare");
  }
}

// A FrameRenderer keeps the scene's shading records from frame to frame (shadeFrameInto): its
// second frame shades with the records its first one built, and must shade exactly as a frame
// that builds all of its own; if a record held anything of the frame that built it (or were
// read before it was complete), the second frame would differ.
TEST(PerfEquality, ShadingRecordsKeptAcrossFramesEqualFresh) {
  for (const char* name : {"multilight", "year2002", "spheres"}) {
    const Scene scene = builtinScene(name);
    FrameOptions options;
    options.width = 203;
    options.height = 117;
    const FrameRenderer renderer(scene, options);
    FrameResult first, second;
    renderer.render(first);
    renderer.render(second);
    const FrameResult fresh = renderFrame(scene, options);
    EXPECT_TRUE(first.color == fresh.color) << name;
    EXPECT_TRUE(second.color == fresh.color) << name;
  }
}

}  // namespace test_perf_equality
}  // namespace penumbra
