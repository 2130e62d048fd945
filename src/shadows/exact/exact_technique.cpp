// Exact soft shadow volumes. For a visible point p and the light's N samples s_i, D(s_i) is the
// number of triangles the segment from p to s_i crosses, and the visibility is the fraction of
// samples with D = 0 (what the oracle's rays to the same samples find). Walking from the light
// centre c to a sample, D changes only where the walk crosses the projection of a silhouette
// edge seen from p (Laine et al. 2005, section 3; docs/exact-soft-shadows.md derives the signs
// used here), so
//   D(s_i) = D(c) + sum over silhouette edges e of [c -> s_i crosses e's projection] * delta_e,
// with D(c) the two-sided hard shadow volume's stencil at the pixel (shadow_stencil.h) and
// delta_e the signed number of e's triangles entered. Per light: the potential silhouette edges
// and their screen tiles (potential_edges.h). Per tile and pixel: the shaded point (the oracle's
// ray origin), each binned edge's silhouette test and projection in double, and for the edges
// that overlap the light one pass over the samples (sample_kernel.h).
//
// The visible triangle itself is left out of every count: a sample behind its plane is blocked
// (the oracle decides the same, RayStart::intoSurface), and the stencil counted it exactly when
// the light centre is behind it.
#include "shadows/exact/exact_technique.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/timer.h"
#include "shadows/exact/potential_edges.h"
#include "shadows/exact/sample_kernel.h"
#include "shadows/facing_away.h"
#include "shadows/reference/light_sampling.h"
#include "shadows/reference/ray_origin.h"
#include "shadows/volume/shadow_stencil.h"

namespace penumbra {
namespace {

constexpr int kMaxSamples = 4096;

struct alignas(kSampleAlignment) FloatBlock {
  float v[kSampleBlock];
};
struct alignas(kSampleAlignment) IntBlock {
  int32_t v[kSampleBlock];
};

// The fixed sample set as polar points of the unit disk (light_sampling.h), padded to whole
// blocks with points at the centre that are never counted.
struct SampleSet {
  int n = 0;
  size_t padded = 0;
  std::vector<DiskPoint> disk;  // n entries
  std::vector<float> radius2, cos_phi, sin_phi;  // padded entries
};

SampleSet makeSampleSet(int n, uint64_t seed) {
  SampleSet set;
  set.n = n;
  set.padded = (size_t(n) + kSampleBlock - 1) / kSampleBlock * kSampleBlock;
  std::vector<vec2> square(static_cast<size_t>(n));
  fixedSamples(n, seed, square.data());
  set.radius2.assign(set.padded, 0.0f);
  set.cos_phi.assign(set.padded, 1.0f);
  set.sin_phi.assign(set.padded, 0.0f);
  for (int i = 0; i < n; ++i) {
    const DiskPoint d = concentricDisk(square[size_t(i)]);
    set.disk.push_back(d);
    set.radius2[size_t(i)] = d.radius * d.radius;
    set.cos_phi[size_t(i)] = d.cos_phi;
    set.sin_phi[size_t(i)] = d.sin_phi;
  }
  return set;
}

// Per-thread scratch of one tile's pixels.
struct Scratch {
  std::vector<FloatBlock> x, y;
  std::vector<IntBlock> count;
  std::vector<uint8_t> into;
  std::vector<SampleEdge> edges;
  explicit Scratch(const SampleSet& s)
      : x(s.padded / kSampleBlock), y(s.padded / kSampleBlock), count(s.padded / kSampleBlock),
        into(size_t(s.n)) {}
};

struct PixelWork {
  uint64_t tests = 0;  // (pixel, edge) pairs examined
  uint64_t inside = 0;  // of those, edges that changed samples
};

class ExactSoftShadows final : public PreparedTechnique {
 public:
  ExactSoftShadows(const ExactOptions& options, const Scene& scene)
      : options_(options), scene_(scene), samples_(makeSampleSet(options.samples, options.seed)) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  float pixelVisibility(int x, int y, float depth, uint32_t primitive, int32_t stencil,
                        const uint32_t* edge_begin, const uint32_t* edge_end,
                        const PotentialEdges& edges, const RayOrigins& origins,
                        const Light& light, bool simd, Scratch& scratch, PixelWork& work) const;

  ExactOptions options_;
  const Scene& scene_;
  SampleSet samples_;
};

float ExactSoftShadows::pixelVisibility(int x, int y, float depth, uint32_t primitive,
                                        int32_t stencil, const uint32_t* edge_begin,
                                        const uint32_t* edge_end, const PotentialEdges& edges,
                                        const RayOrigins& origins, const Light& light, bool simd,
                                        Scratch& scratch, PixelWork& work) const {
  const dvec3 c(light.center);
  const double r = light.radius;
  const RayStart start = origins.start(x, y, depth, primitive);
  // A point inside the light sees all of it (as the oracle has it).
  if (glm::length(c - start.origin) <= r) return 1.0f;
  // The oracle's rays start at the float origin; every test here is made from that point.
  const dvec3 p(vec3(start.origin));
  const SphereCone cone = makeSphereCone(start.origin, c, r);
  const dvec3 axis(cone.axis), tangent(cone.tangent), bitangent(cone.bitangent);
  const double omc = cone.one_minus_cos_max;
  // The light's disk on the plane at unit distance along the axis: radius tan(theta_max).
  const double light_radius = std::sqrt(omc * (2.0 - omc)) / (1.0 - omc) * (1.0 + 1e-5);
  const double distance = glm::length(c - p);
  const double z_min = 1e-7 * distance;  // edges are clipped to this depth along the axis
  // D at the centre without the visible triangle (counted when the centre is behind it).
  const int32_t centre_count = stencil - (start.intoSurface(c) ? 1 : 0);

  scratch.edges.clear();
  int64_t reach = 0;  // how far the edges can move any sample's count from the centre's
  for (const uint32_t* it = edge_begin; it != edge_end; ++it) {
    const PotentialEdge& e = edges.edges[*it];
    ++work.tests;
    dvec3 a = e.a - p, b = e.b - p;
    double za = glm::dot(a, axis), zb = glm::dot(b, axis);
    if (za <= z_min && zb <= z_min) continue;  // behind the point: no ray toward the light
    // Silhouette from p: the signed number of the edge's triangles on each side of the plane
    // through p and the edge, from each triangle's own plane (EdgeTriangle). Left out: the
    // visible triangle, and triangles whose plane has p and the light centre on one side (no
    // segment from p to the light crosses them while the plane misses the light; the stencil
    // does not count them at the centre either).
    int32_t weight = 0;
    for (uint32_t k = 0; k < e.triangle_count; ++k) {
      const EdgeTriangle& t = edges.triangles[e.first_triangle + k];
      if (t.id == primitive) continue;
      const double at_p = glm::dot(t.normal, p) + t.offset;
      if ((at_p > 0.0) == t.light_above) continue;
      weight -= t.winding * ((at_p > 0.0) - (at_p < 0.0));
    }
    if (weight == 0) continue;
    // Clip to z >= z_min: the part behind projects outside the light.
    if (za < z_min) {
      a += (b - a) * ((z_min - za) / (zb - za));
      za = z_min;
    } else if (zb < z_min) {
      b += (a - b) * ((z_min - zb) / (za - zb));
      zb = z_min;
    }
    const dvec2 a2(glm::dot(a, tangent) / za, glm::dot(a, bitangent) / za);
    const dvec2 b2(glm::dot(b, tangent) / zb, glm::dot(b, bitangent) / zb);
    // Distance from the centre (0, 0) to the projected segment: beyond the light, no sample.
    const dvec2 ab = b2 - a2;
    const double ab2 = glm::dot(ab, ab);
    const double t = ab2 > 0.0 ? std::clamp(-glm::dot(a2, ab) / ab2, 0.0, 1.0) : 0.0;
    if (glm::length(a2 + t * ab) > light_radius) continue;
    // Sector lines through the centre and each projected end: n_a = axis x a gives the value
    // -a.B x + a.T y, up to the positive factor 1 / z_a. Normalised in double, then rounded,
    // the same way for every edge sharing the end, so the half-open rule is watertight.
    auto sectorLine = [](const dvec3& v, const dvec3& tv, const dvec3& bv, float out[2]) {
      const double s = -glm::dot(v, bv), u = glm::dot(v, tv);
      const double scale = std::max(std::fabs(s), std::fabs(u));
      out[0] = float(s / scale);
      out[1] = float(u / scale);
      return dvec2(s / scale, u / scale);
    };
    SampleEdge s;
    const dvec2 la = sectorLine(a, tangent, bitangent, s.sector_a);
    const dvec2 lb = sectorLine(b, tangent, bitangent, s.sector_b);
    const double a_at_b = la.x * b2.x + la.y * b2.y;
    const double b_at_a = lb.x * a2.x + lb.y * a2.y;
    if (a_at_b == 0.0 || b_at_a == 0.0) continue;  // the centre on the edge's line: a tie
    s.a_side = a_at_b > 0.0;
    s.b_side = b_at_a > 0.0;
    // The edge's line: the plane through p and the edge, n . (T x + B y + axis).
    const dvec3 n = glm::cross(a, b);
    const dvec3 l(glm::dot(n, tangent), glm::dot(n, bitangent), glm::dot(n, axis));
    const double l_scale = std::max({std::fabs(l.x), std::fabs(l.y), std::fabs(l.z)});
    s.line[0] = float(l.x / l_scale);
    s.line[1] = float(l.y / l_scale);
    s.line[2] = float(l.z / l_scale);
    s.centre_side = s.line[2] >= 0.0f;
    // Crossing from the centre's side onto the other: the triangles on that side (+1 each) are
    // entered, those on the centre's side (-1 each) left.
    s.delta = s.centre_side ? -weight : weight;
    scratch.edges.push_back(s);
    reach += std::abs(weight);
    ++work.inside;
  }

  const int n = samples_.n;
  // Samples behind the visible triangle's plane are blocked by it; only where the light
  // reaches across that plane does any sample need the test (the oracle's, sample by sample).
  int into_count = 0;
  bool any_into = false;
  const double normal_length = glm::length(start.plane_normal);
  if (normal_length > 0.0 &&
      glm::dot(start.plane_normal, c - start.plane_point) / normal_length <= r * (1.0 + 1e-4)) {
    any_into = true;
    for (int i = 0; i < n; ++i) {
      const ConeSample s = sampleSphereCone(cone, samples_.disk[size_t(i)]);
      const bool into = start.intoSurface(start.origin + dvec3(s.direction) * double(s.distance));
      scratch.into[size_t(i)] = into;
      into_count += into;
    }
  }
  if (scratch.edges.empty()) return centre_count == 0 ? float(n - into_count) / float(n) : 0.0f;
  if (centre_count > reach) return 0.0f;  // no sample's count can come down to 0

  // Sample positions on the plane at unit distance (sampleSphereCone's angles, in float).
  float* sx = scratch.x.data()->v;
  float* sy = scratch.y.data()->v;
  int32_t* count = scratch.count.data()->v;
  const float omc_max = cone.one_minus_cos_max;
  for (size_t i = 0; i < samples_.padded; ++i) {
    const float one_minus_cos = samples_.radius2[i] * omc_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float tan_theta = std::sqrt(one_minus_cos * (2.0f - one_minus_cos)) / cos_theta;
    sx[i] = tan_theta * samples_.cos_phi[i];
    sy[i] = tan_theta * samples_.sin_phi[i];
    count[i] = centre_count;
  }
  for (const SampleEdge& s : scratch.edges)
    addEdgeCrossings(s, sx, sy, count, samples_.padded, simd);
  int lit = 0;
  for (int i = 0; i < n; ++i)
    lit += count[i] == 0 && !(any_into && scratch.into[size_t(i)]);
  return float(lit) / float(n);
}

TechniqueResult ExactSoftShadows::render(const Light& light, const View& view,
                                         const EyeBuffers& eye,
                                         const RenderContext& context) const {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  PENUMBRA_CHECK(std::isfinite(light.radius) && light.radius >= 0.0f,
                 "light radius {} must be a finite number >= 0", light.radius);
  const int width = eye.depth.width(), height = eye.depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  TechniqueResult result;
  Stats& stats = result.stats;
  ShadowStencilOptions stencil_options;
  stencil_options.simd = context.simd;
  if (light.radius == 0.0f) {
    // A point light: the hard shadow volume, bit for bit.
    const Image<int32_t> stencil =
        shadowStencil(scene_, light.center, view, eye, stencil_options, stats);
    PassTimer timer(stats, "resolve");
    resolveVisibility(scene_, light, view, eye, result.visibility,
                      [&](int x, int y) { return stencil.at(x, y) != 0 ? 0.0f : 1.0f; });
    return result;
  }
  // Two-sided casters: the stencil counts every triangle between the point and the centre.
  stencil_options.policy = CasterPolicy::TwoSided;
  const Image<int32_t> stencil =
      shadowStencil(scene_, light.center, view, eye, stencil_options, stats);

  PotentialEdges edges;
  {
    PassTimer timer(stats, "edges");
    edges = potentialEdges(scene_, light);
    stats.wedges += edges.edges.size();
  }
  EdgeBins bins;
  {
    PassTimer timer(stats, "binning");
    bins = binEdges(edges, light, view, eye.depth, options_.tile_level,
                    kMaxOriginOffsetFootprints);
    stats.tiles_tested += bins.tiles_tested;
    stats.tiles_culled += bins.tiles_culled;
  }

  Image<float> soft(width, height, 1.0f);
  {
    PassTimer timer(stats, "samples");
    const RayOrigins origins(scene_, view);
    const FacingAway away(scene_, light, view);
    const size_t tiles = size_t(bins.columns) * size_t(bins.rows);
    const int tile = 1 << bins.level;
    std::vector<PixelWork> tile_work(tiles);
    std::vector<uint64_t> tile_reads(tiles, 0);
    ProgressBar progress("exact", tiles, context.show_progress);
    parallelFor(tiles, [&](size_t index) {
      thread_local std::unique_ptr<Scratch> scratch;
      if (!scratch || scratch->into.size() != size_t(samples_.n))
        scratch = std::make_unique<Scratch>(samples_);
      const int tx = int(index % size_t(bins.columns)), ty = int(index / size_t(bins.columns));
      const uint32_t* begin = bins.edges.data() + bins.begin[index];
      const uint32_t* end = bins.edges.data() + bins.begin[index + 1];
      for (int y = ty * tile; y < std::min(height, ty * tile + tile); ++y) {
        for (int x = tx * tile; x < std::min(width, tx * tile + tile); ++x) {
          const float depth = eye.depth.depth.at(x, y);
          const uint32_t id = eye.primitive.at(x, y);
          if (!(depth > 0.0f) || id == kNoPrimitive || away(id)) continue;
          ++tile_reads[index];
          soft.at(x, y) = pixelVisibility(x, y, depth, id, stencil.at(x, y), begin, end, edges,
                                          origins, light, context.simd, *scratch,
                                          tile_work[index]);
        }
      }
      progress.add();
    });
    progress.finish();
    for (size_t t = 0; t < tiles; ++t) {
      stats.z_reads += tile_reads[t];
      stats.penumbra_tests += tile_work[t].tests;
      stats.penumbra_inside += tile_work[t].inside;
    }
  }
  {
    PassTimer timer(stats, "resolve");
    resolveVisibility(scene_, light, view, eye, result.visibility,
                      [&](int x, int y) { return soft.at(x, y); });
  }
  return result;
}

}  // namespace

TechniqueInfo exactTechnique() {
  TechniqueInfo info;
  info.name = "exact";
  info.summary = "exact soft shadow volumes: the oracle's answer for a fixed light sample set, "
                 "counted from silhouette edges without rays (Laine et al. 2005)";
  info.traits.soft = true;
  info.traits.exact = true;
  // Against the 1024-ray oracle: the sampling error of 256 fixed samples, like the oracle's own
  // at 256 rays.
  info.traits.covered_mae_bound = 0.01;
  info.traits.penumbra_mae_bound = 0.03;
  info.options =
      OptionTableBuilder<ExactOptions>()
          .integer("samples", "light samples per pixel (one fixed stratified set)",
                   &ExactOptions::samples, 1, kMaxSamples)
          .integer("seed", "random seed of the sample set (the oracle's --seed with "
                           "--sample-set fixed gives the same set)",
                   &ExactOptions::seed, 0, INT64_MAX)
          .integer(
              "tile-size", "edge binning tile size in pixels, a power of two in 4..64", 4, 64,
              [](ExactOptions& o, int64_t v) {
                PENUMBRA_CHECK((v & (v - 1)) == 0, "--tile-size {} is not a power of two", v);
                int level = 0;
                while ((1 << level) < v) ++level;
                o.tile_level = level;
              },
              [](const ExactOptions& o) { return int64_t(1) << o.tile_level; })
          .check([](const ExactOptions& o) {
            PENUMBRA_CHECK(o.tile_level >= 2 && o.tile_level <= 6,
                           "exact: tile level {} is outside 2..6 (4 to 64 pixels)", o.tile_level);
          })
          .describe([](const ExactOptions& o) {
            return fmt::format("{} samples, seed {}, {}x{} tiles", o.samples, o.seed,
                               1 << o.tile_level, 1 << o.tile_level);
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<ExactSoftShadows>(std::any_cast<const ExactOptions&>(options), scene);
  };
  return info;
}

}  // namespace penumbra
