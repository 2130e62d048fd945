#include "shadows/pcss/pcss_kernel.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {
constexpr double kGoldenAngle = 2.399963229728653;  // radians: Vogel's spiral
}  // namespace

VogelSpiral::VogelSpiral(int count) : n(count) {
  for (int k = 0; k < n; ++k) {
    radius.push_back(std::sqrt((k + 0.5) / n));
    cos.push_back(std::cos(k * kGoldenAngle));
    sin.push_back(std::sin(k * kGoldenAngle));
  }
}

void pcssVisibilityScalar(const PcssFace& face, const PcssShape& shape, const PcssPoints& pts,
                          float* visibility, size_t n, uint64_t& reads) {
  const double size = double(face.texels.size);
  for (size_t p = 0; p < n; ++p) {
    const double w = pts.w[p], sx = pts.sx[p], sy = pts.sy[p];
    const double tc = pts.turn_cos[p], ts = pts.turn_sin[p];
    if (!(face.nearest < w)) {
      visibility[p] = pcssFinish(face, shape, w, 0.0, 0.0, 0.0, reads);
      continue;
    }
    // A lookup `offset` texels away compares against the receiver less this bias (a plane of
    // slope `slope` rises by slope x offset texels there).
    const auto receiverAt = [&](double offset) {
      return w - pts.texel[p] * (shape.constant_bias + pts.slope_bias[p] * (offset + 0.5));
    };
    // PcssOccluderTest::Plane: the receiver plane's a, its step at the point itself (-a / w, the
    // point lies on it), and the least height above it that occludes.
    const bool plane = shape.plane_test;  // the depth test may pass no plane arrays
    const double a = plane ? pts.plane_a[p] : 0.0, step_x = plane ? pts.plane_x[p] : 0.0;
    const double step_y = plane ? pts.plane_y[p] : 0.0;
    const double step = -a / w, least = pts.texel[p] * shape.constant_bias;
    // Whether the occluder d read at the texel dx, dy texels (its centre) from the point's
    // projection, `offset` texels out along the spiral, hides part of the light from p.
    const auto occludes = [&](double d, double offset, double dx, double dy) {
      if (!shape.plane_test) return d < receiverAt(offset);
      return d < w && a + d * (step + step_x * dx + step_y * dy) > least;
    };
    // Calls fn(d, offset, dx, dy) for the occluder d under each point of `spiral` scaled to
    // `width` texels and turned by the pixel's angle.
    const auto forSpiral = [&](const VogelSpiral& spiral, double width, auto&& fn) {
      for (int k = 0; k < spiral.n; ++k) {
        const double r = width * spiral.radius[size_t(k)];
        const double c = spiral.cos[size_t(k)] * tc - spiral.sin[size_t(k)] * ts;
        const double s = spiral.sin[size_t(k)] * tc + spiral.cos[size_t(k)] * ts;
        const double tx = std::floor(sx + r * c), ty = std::floor(sy + r * s);
        fn(occluderAt(face.texels, int(tx), int(ty)), r, tx + 0.5 - sx, ty + 0.5 - sy);
      }
    };
    // 1. Blocker search over the disk through which the light can be hidden from p.
    const double search =
        std::min(diskTexels(shape.light_radius, w, face.nearest, face.texels_per_tangent), size);
    double blockers = 0.0, found = 0.0;
    forSpiral(*shape.blocker, search, [&](double d, double offset, double dx, double dy) {
      if (occludes(d, offset, dx, dy)) {
        blockers += d;
        found += 1.0;
      }
    });
    double lit = 0.0;
    if (found > 0.0 && !(found == double(shape.blocker->n) && search == 0.0)) {
      // 2. Penumbra estimate from the average blocker distance; 3. filter over it.
      const double filter = std::min(
          diskTexels(shape.light_radius, w, blockers / found, face.texels_per_tangent), size);
      forSpiral(*shape.filter, filter, [&](double d, double offset, double dx, double dy) {
        if (!occludes(d, offset, dx, dy)) lit += 1.0;
      });
    }
    visibility[p] = pcssFinish(face, shape, w, found, search, lit, reads);
  }
}

}  // namespace penumbra
