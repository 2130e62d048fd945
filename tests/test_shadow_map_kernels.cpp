// The shadow-map and PCSS lookup kernels (map_lookup_kernel.h, pcss_kernel.h): the SIMD
// versions give the scalar twins' answers bit for bit on random batches, including points on
// texel boundaries, on a face's edges (where a cube face meets the next: project() puts such
// points at 0 or size) and kernels reaching past the border; and the scalar twins answer a
// hand-checked case. Runs in well under a second.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/simd_dispatch.h"
#include "shadows/pcss/pcss_kernel.h"
#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"

namespace penumbra {
namespace test_shadow_map_kernels {

constexpr int kSize = 32;
constexpr double kNear = 0.01;

// A face of random occluders at distances 1..10 (reversed-Z near / d), a quarter of it empty.
std::vector<float> randomFace(std::mt19937& rng) {
  std::uniform_real_distribution<double> distance(1.0, 10.0);
  std::uniform_int_distribution<int> empty(0, 3);
  std::vector<float> texels(size_t(kSize * kSize));
  for (float& t : texels) t = empty(rng) == 0 ? 0.0f : float(kNear / distance(rng));
  return texels;
}

// Positions across and past the face, a third of them on texel corners and edges (0, size,
// whole and half texels), so floor() meets exact integers and the clamp meets the border.
std::vector<double> randomPositions(std::mt19937& rng, size_t n) {
  std::uniform_real_distribution<double> anywhere(-3.0, kSize + 3.0);
  std::uniform_int_distribution<int> kind(0, 5), whole(-2, kSize + 2);
  std::vector<double> s(n);
  for (double& v : s) {
    const int k = kind(rng);
    v = k == 0 ? double(whole(rng)) : k == 1 ? whole(rng) + 0.5 : k == 2 ? (whole(rng) & 1) * kSize
                                                                         : anywhere(rng);
  }
  return s;
}

// A wrong SIMD twin (lanes reading the wrong texels, another floor or clamp at the border, a
// different comparison at equal distances) gives other visibilities here.
TEST(ShadowMapKernels, PcfSimdEqualsScalarOnRandomBatchesAndAtTheBorder) {
  std::mt19937 rng(12);
  const size_t n = 8 * kLookupBlock;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<float> texels = randomFace(rng);
    const FaceTexels face{texels.data(), kSize, kNear};
    const std::vector<double> sx = randomPositions(rng, n), sy = randomPositions(rng, n);
    std::vector<double> receiver(n);
    std::uniform_real_distribution<double> distance(0.5, 11.0);
    for (size_t p = 0; p < n; ++p) {
      // Every eighth receiver sits exactly at a stored occluder: ">=" must hold in both.
      receiver[p] = p % 8 == 0 ? occluderAt(face, int(sx[p]), int(sy[p])) : distance(rng);
    }
    // Half the points with a ring bias: the taps' receivers must step the same way in both.
    std::vector<double> ring_bias(n, 0.0);
    for (size_t p = 0; p < n; p += 2) ring_bias[p] = 0.01 * double(p % 7);
    for (const int kernel : {1, 3, 5, 15}) {
      std::vector<float> simd(n), scalar(n);
      pcfVisibility(face, sx.data(), sy.data(), receiver.data(), ring_bias.data(), kernel,
                    simd.data(), n, true);
      pcfVisibilityScalar(face, sx.data(), sy.data(), receiver.data(), ring_bias.data(), kernel,
                          scalar.data(), n);
      for (size_t p = 0; p < n; ++p)
        ASSERT_EQ(simd[p], scalar[p]) << "kernel " << kernel << " point " << p << " at ("
                                      << sx[p] << ", " << sy[p] << ")";
    }
  }
}

// A wrong kernel origin or border clamp gives another fraction: one occluder at texel (0, 0),
// nearer than the receiver, in an otherwise empty 4 x 4 face.
TEST(ShadowMapKernels, PcfScalarCountsTheHandCheckedKernel) {
  std::vector<float> texels(16, 0.0f);
  texels[0] = float(kNear / 2.0);
  const FaceTexels face{texels.data(), 4, kNear};
  std::vector<double> sx(kLookupBlock, 1.5), sy(kLookupBlock, 1.5), receiver(kLookupBlock, 5.0);
  sx[1] = 0.2;  // kernel at the corner: (-1..1) x (0..2) clamps three taps onto texel (0, y)
  sy[1] = 1.5;
  sx[2] = 3.9;  // far side: no tap reaches x = 0
  receiver[3] = 1.5;  // in front of the occluder: lit
  std::vector<double> ring_bias(kLookupBlock, 0.0);
  ring_bias[4] = 3.0;  // the occluder at (0, 0) is a ring-1 tap: 5 - 3 = 2 is in front of it
  std::vector<float> v(kLookupBlock);
  pcfVisibilityScalar(face, sx.data(), sy.data(), receiver.data(), ring_bias.data(), 3, v.data(),
                      kLookupBlock);
  EXPECT_FLOAT_EQ(v[0], 8.0f / 9.0f);  // taps (0..2) x (0..2): one on the occluder
  EXPECT_FLOAT_EQ(v[1], 7.0f / 9.0f);  // taps at x = -1 and x = 0 of row 0 both read (0, 0)
  EXPECT_FLOAT_EQ(v[2], 1.0f);
  EXPECT_FLOAT_EQ(v[3], 1.0f);
  EXPECT_FLOAT_EQ(v[4], 1.0f);
  pcfVisibility(face, sx.data(), sy.data(), receiver.data(), ring_bias.data(), 3, v.data(),
                kLookupBlock, true);
  EXPECT_FLOAT_EQ(v[1], 7.0f / 9.0f);
  EXPECT_FLOAT_EQ(v[4], 1.0f);
}

// A wrong SIMD twin (another spiral turn, blocker average, early-out or read count) gives other
// visibilities or counts here. Batches mix points with nothing in front (w below the nearest
// occluder), fully lit and partly shadowed points, and a point light (radius 0).
TEST(ShadowMapKernels, PcssSimdEqualsScalarOnRandomBatches) {
  std::mt19937 rng(7);
  const size_t n = 8 * kLookupBlock;
  size_t partly = 0;  // points strictly between lit and dark: the filter step ran
  for (int trial = 0; trial < 24; ++trial) {
    const std::vector<float> texels = randomFace(rng);
    PcssFace face;
    face.texels = {texels.data(), kSize, kNear};
    face.nearest = 1.0 + 0.01 * trial;
    face.texels_per_tangent = kSize / 2.0;
    const VogelSpiral blocker(trial % 3 == 0 ? 7 : 16), filter(trial % 3 == 0 ? 13 : 32);
    PcssShape shape;
    shape.light_radius = trial % 4 == 0 ? 0.0 : 0.05 * trial;
    shape.constant_bias = trial % 2 == 0 ? 1.0 : 0.0;
    shape.plane_test = trial % 3 == 1;  // PcssOccluderTest::Plane on a third of the trials
    shape.blocker = &blocker;
    shape.filter = &filter;
    const std::vector<double> sx = randomPositions(rng, n), sy = randomPositions(rng, n);
    std::vector<double> w(n), texel(n), slope_bias(n), turn_cos(n), turn_sin(n);
    std::vector<double> plane_a(n), plane_x(n), plane_y(n);
    std::uniform_real_distribution<double> distance(0.5, 12.0), unit(0.0, 1.0);
    for (size_t p = 0; p < n; ++p) {
      w[p] = distance(rng);
      texel[p] = 2.0 * w[p] / kSize;
      slope_bias[p] = 3.0 * unit(rng);
      const double turn = 6.283185307179586 * unit(rng);
      turn_cos[p] = std::cos(turn);
      turn_sin[p] = std::sin(turn);
      // A receiver plane under the light centre, tilted by up to 45 degrees per texel step.
      plane_a[p] = w[p] * (0.5 + unit(rng));
      plane_x[p] = (unit(rng) - 0.5) * texel[p];
      plane_y[p] = (unit(rng) - 0.5) * texel[p];
    }
    const PcssPoints points{sx.data(),         sy.data(),       w.data(),         texel.data(),
                            slope_bias.data(), turn_cos.data(), turn_sin.data(),  plane_a.data(),
                            plane_x.data(),    plane_y.data()};
    std::vector<float> simd(n), scalar(n);
    uint64_t simd_reads = 0, scalar_reads = 0;
    pcssVisibility(face, shape, points, simd.data(), n, simd_reads, true);
    pcssVisibilityScalar(face, shape, points, scalar.data(), n, scalar_reads);
    for (size_t p = 0; p < n; ++p)
      ASSERT_EQ(simd[p], scalar[p]) << "trial " << trial << " point " << p;
    EXPECT_EQ(simd_reads, scalar_reads) << "trial " << trial;
    for (const float v : scalar) partly += v > 0.0f && v < 1.0f;
  }
  EXPECT_GT(partly, n) << "the batches must exercise the filter, not only the early outs";
}

// The tabled spiral turned by the angle-sum formula is Vogel's spiral turned directly: a wrong
// table (radius, angle step) would move every sample.
TEST(ShadowMapKernels, TabledSpiralTurnsLikeTheDirectFormula) {
  const VogelSpiral spiral(32);
  const double turn = 1.234;
  for (int k = 0; k < 32; ++k) {
    const double a = k * 2.399963229728653 + turn;
    EXPECT_NEAR(spiral.radius[size_t(k)], std::sqrt((k + 0.5) / 32), 0.0);
    EXPECT_NEAR(spiral.cos[size_t(k)] * std::cos(turn) - spiral.sin[size_t(k)] * std::sin(turn),
                std::cos(a), 1e-13);
    EXPECT_NEAR(spiral.sin[size_t(k)] * std::cos(turn) + spiral.cos[size_t(k)] * std::sin(turn),
                std::sin(a), 1e-13);
  }
}

}  // namespace test_shadow_map_kernels
}  // namespace penumbra
