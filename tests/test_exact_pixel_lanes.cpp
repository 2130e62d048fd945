// The exact soft shadow volumes test each candidate edge at up to kEdgeLanes pixels at once
// (edgeAtPixels, SIMD over the pixels in double) and leave to the per-pixel edgeAtPixel only
// the pixels where a triangle cutting the light needs the clipped classification. Both twins
// must give exactly what edgeAtPixel gives: the same accepted pixels, the same sector lines,
// sides, delta, weight and sample runs, bit for bit, or `exact` would no longer match the oracle
// on the pixels the batches decide (and the SIMD and scalar builds would differ).
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "shadows/exact/light_samples.h"
#include "shadows/exact/pixel_edges.h"

namespace penumbra {
namespace test_exact_pixel_lanes {

struct Case {
  PotentialEdge edge;
  std::vector<EdgeTriangle> triangles;
};

// A pixel's frame as setupPixel makes it, for a shaded point p and the light (c, r).
PixelBasis frameAt(const dvec3& p, const dvec3& c, double r, uint32_t primitive) {
  PixelBasis f;
  f.ready = true;
  f.primitive = primitive;
  f.p = p;
  f.cone = makeSphereCone(p, c, r);
  f.axis = dvec3(f.cone.axis);
  f.tangent = dvec3(f.cone.tangent);
  f.bitangent = dvec3(f.cone.bitangent);
  const double omc = f.cone.one_minus_cos_max;
  f.light_radius = std::sqrt(omc * (2.0 - omc)) / (1.0 - omc) * (1.0 + 1e-5);
  f.z_min = 1e-7 * glm::length(c - p);
  f.light_near = glm::length(c - p) - r;
  f.cos_max = 1.0 - omc;
  f.sin_max = std::sqrt(omc * (2.0 - omc));
  return f;
}

bool sameEdge(const SampleEdge& a, const SampleEdge& b) {
  return std::memcmp(a.sector_a, b.sector_a, sizeof(a.sector_a)) == 0 &&
         std::memcmp(a.sector_b, b.sector_b, sizeof(a.sector_b)) == 0 &&
         std::memcmp(a.line, b.line, sizeof(a.line)) == 0 && a.a_side == b.a_side &&
         a.b_side == b.b_side && a.centre_side == b.centre_side && a.delta == b.delta;
}

bool sameRuns(const SampleRuns& a, const SampleRuns& b) {
  return a.begin[0] == b.begin[0] && a.begin[1] == b.begin[1] && a.end[0] == b.end[0] &&
         a.end[1] == b.end[1];
}

// Random edges between points below a light and the light, with one to four triangles each
// (some of them the pixel's own triangle, some with planes through the light, some with
// opposite vertices behind the light), at batches of random points, a few of them behind the
// edge or beside its line (ties) or with the edge crossing z_min (clipped).
TEST(ExactPixelLanes, BatchedTwinsGiveWhatThePerPixelTestGives) {
  std::mt19937_64 random(20051119);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * (double(random() >> 11) * 0x1.0p-53);
  };
  const dvec3 c(0.3, 6.0, -0.2);
  const double r = 0.6;
  // 256 samples (16 blocks: the SIMD twin counts blocks) and 4096 (256 blocks: it searches).
  const SortedSamples samples = makeSampleSet(256, 3), many = makeSampleSet(4096, 5);
  int accepted = 0, deferred = 0, rejected = 0, clipped = 0, own = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // The points: a patch of a floor, or scattered.
    PixelBasis frames[kEdgeLanes];
    const int count = 1 + int(random() % kEdgeLanes);
    const dvec3 centre(uniform(-2, 2), uniform(-0.5, 0.5), uniform(-2, 2));
    const double spread = random() % 2 ? 1e-3 : 1.0;
    for (int k = 0; k < count; ++k) {
      const dvec3 p = centre + spread * dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      frames[k] = frameAt(p, c, r, uint32_t(100 + random() % 3));
    }
    // The edge: somewhere between the patch and the light, or crossing the patch's level.
    Case s;
    const double h = uniform(0.0, 1.0);
    const dvec3 mid = centre + h * (c - centre) +
                      dvec3(uniform(-1, 1), uniform(-0.3, 0.3), uniform(-1, 1)) * (0.2 + h);
    const dvec3 along = glm::normalize(dvec3(uniform(-1, 1), uniform(-0.5, 0.5), uniform(-1, 1)));
    const double half = uniform(0.01, 1.5);
    s.edge.a = mid - half * along;
    s.edge.b = mid + half * along;
    if (random() % 8 == 0) s.edge.b = centre + dvec3(uniform(-1, 1), -0.2, uniform(-1, 1));
    const int triangles = 1 + int(random() % 4);
    s.edge.first_triangle = 0;
    s.edge.triangle_count = uint32_t(triangles);
    for (int k = 0; k < triangles; ++k) {
      EdgeTriangle t;
      t.id = uint32_t(100 + random() % 6);  // sometimes a pixel's own triangle
      dvec3 opposite = mid + dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (random() % 4 == 0) opposite = c + dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      t.opposite = opposite;
      t.winding = random() % 2 ? 1 : -1;
      dvec3 n = glm::normalize(glm::cross(s.edge.b - s.edge.a, opposite - s.edge.a));
      if (t.winding < 0) n = -n;
      t.normal = n;
      t.offset = -glm::dot(n, s.edge.a);
      const double at_c = glm::dot(n, c) + t.offset;
      t.light_above = at_c > 0.0;
      t.cuts = std::fabs(at_c) < r;
      s.triangles.push_back(t);
    }
    PixelLanes lanes;
    lanes.count = count;
    for (int k = 0; k < count; ++k) lanes.setLane(k, frames[k]);
    EdgeLanes simd, scalar;
    const SortedSamples& set = trial % 3 == 0 ? many : samples;
    const uint32_t simd_passed =
        edgeAtPixels(s.edge, s.triangles.data(), lanes, set, simd, true);
    const uint32_t scalar_passed =
        edgeAtPixelsScalar(s.edge, s.triangles.data(), lanes, set, scalar);
    ASSERT_EQ(simd_passed, scalar_passed) << "trial " << trial;
    ASSERT_EQ(simd.deferred, scalar.deferred) << "trial " << trial;
    ASSERT_EQ(simd_passed & simd.deferred, 0u);
    for (int k = 0; k < count; ++k) {
      const PixelBasis& f = frames[k];
      own += f.primitive == s.triangles[0].id;
      clipped += (glm::dot(s.edge.a - f.p, f.axis) < f.z_min) !=
                 (glm::dot(s.edge.b - f.p, f.axis) < f.z_min);
      if ((simd.deferred >> k) & 1u) {
        ++deferred;
        continue;
      }
      PixelEdge expected;
      int32_t weight = 0;
      const bool pass = edgeAtPixel(s.edge, s.triangles.data(), f, set, expected, weight);
      ASSERT_EQ(pass, bool((simd_passed >> k) & 1u)) << "trial " << trial << " lane " << k;
      if (!pass) {
        ++rejected;
        continue;
      }
      ++accepted;
      for (const EdgeLanes* out : {&simd, &scalar}) {
        EXPECT_TRUE(sameEdge(out->edge[k], expected.edge)) << "trial " << trial << " lane " << k;
        EXPECT_EQ(out->weight[k], weight);
        EXPECT_TRUE(sameRuns(out->runs[k], expected.runs)) << "trial " << trial << " lane " << k;
      }
    }
  }
  // Every kind of lane occurred, or the comparison proved little.
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
  EXPECT_GT(deferred, 50);
  EXPECT_GT(clipped, 50);
  EXPECT_GT(own, 500);
}

}  // namespace test_exact_pixel_lanes
}  // namespace penumbra
