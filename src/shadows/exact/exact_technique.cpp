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
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/timer.h"
#include "shadows/exact/edge_screen_test.h"
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

// A number in [0, 4) that increases with the angle of (x, y) from the x axis as atan2 does, for
// a fraction of its cost (wedge_frame.cpp uses the same).
double pseudoAngle(double x, double y) {
  const double sum = std::fabs(x) + std::fabs(y);
  if (!(sum > 0.0)) return 0.0;
  const double p = y / sum;  // in [-1, 1]
  return x >= 0.0 ? (p >= 0.0 ? p : 4.0 + p) : 2.0 - p;
}

// The fixed sample set as polar points of the unit disk (light_sampling.h), sorted by angle,
// padded to whole blocks with points at the centre that are never counted. A sample's angle
// around the light centre on the sample plane is its disk angle at every pixel (only its
// distance from the centre depends on the pixel), so the samples an edge's sector can hold are
// one or two runs of this order: the pass over the samples visits only those blocks.
struct SampleSet {
  int n = 0;
  size_t padded = 0;
  std::vector<DiskPoint> disk;  // n entries
  // Per block of kSampleBlock samples, the pseudo-angles of its first and last real sample.
  std::vector<double> block_first, block_last;
  std::vector<float> radius2, cos_phi, sin_phi;  // padded entries
};

SampleSet makeSampleSet(int n, uint64_t seed) {
  SampleSet set;
  set.n = n;
  set.padded = (size_t(n) + kSampleBlock - 1) / kSampleBlock * kSampleBlock;
  std::vector<vec2> square(static_cast<size_t>(n));
  fixedSamples(n, seed, square.data());
  for (int i = 0; i < n; ++i) set.disk.push_back(concentricDisk(square[size_t(i)]));
  auto angle = [](const DiskPoint& d) { return pseudoAngle(d.cos_phi, d.sin_phi); };
  std::stable_sort(set.disk.begin(), set.disk.end(),
                   [&](const DiskPoint& a, const DiskPoint& b) { return angle(a) < angle(b); });
  set.radius2.assign(set.padded, 0.0f);
  set.cos_phi.assign(set.padded, 1.0f);
  set.sin_phi.assign(set.padded, 0.0f);
  for (int i = 0; i < n; ++i) {
    const DiskPoint& d = set.disk[size_t(i)];
    set.radius2[size_t(i)] = d.radius * d.radius;
    set.cos_phi[size_t(i)] = d.cos_phi;
    set.sin_phi[size_t(i)] = d.sin_phi;
  }
  for (size_t b = 0; b < set.padded; b += kSampleBlock) {
    set.block_first.push_back(angle(set.disk[b]));
    set.block_last.push_back(angle(set.disk[std::min(size_t(n), b + kSampleBlock) - 1]));
  }
  return set;
}

// The blocks of samples whose pseudo-angle may lie in [from, to] (from in [0, 4), to - from
// < 2, the half turn; to may pass 4 and wrap): one or two runs [begin, end) of whole blocks.
struct SampleRuns {
  uint32_t begin[2] = {0, 0}, end[2] = {0, 0};
};
SampleRuns sampleRuns(const SampleSet& set, double from, double to) {
  // Far wider than the float error of the kernel's sector lines (some 1e-7 relative); the
  // pseudo-angle grows at least half as fast as the angle.
  constexpr double kSlack = 1e-5;
  from -= kSlack;
  to += kSlack;
  // Blocks [first block whose last sample >= lo, first block whose first sample > hi).
  auto run = [&](double lo, double hi, uint32_t& begin, uint32_t& end) {
    const size_t b = size_t(std::lower_bound(set.block_last.begin(), set.block_last.end(), lo) -
                            set.block_last.begin());
    const size_t e = size_t(std::upper_bound(set.block_first.begin(), set.block_first.end(), hi) -
                            set.block_first.begin());
    begin = uint32_t(b * kSampleBlock);
    end = uint32_t(std::max(b, e) * kSampleBlock);
  };
  SampleRuns runs;
  if (from < 0.0) {
    run(0.0, to, runs.begin[0], runs.end[0]);
    run(from + 4.0, 4.0, runs.begin[1], runs.end[1]);
  } else if (to >= 4.0) {
    run(from, 4.0, runs.begin[0], runs.end[0]);
    run(0.0, to - 4.0, runs.begin[1], runs.end[1]);
  } else {
    run(from, to, runs.begin[0], runs.end[0]);
  }
  return runs;
}

// A visible point and the light as it sees it: the oracle's ray origin and sample cone.
struct PixelFrame {
  // Set up only once an edge may matter (setupPixel); until then all that is known is the
  // stencil, and the pixel's triangle has the whole light in front of it (ClearOfLight).
  bool ready = false;
  int32_t stencil = 0;
  uint32_t primitive = kNoPrimitive;  // the visible triangle, left out of every count
  RayStart start;
  dvec3 p{0.0};  // the float origin the oracle's rays start from, widened
  SphereCone cone;
  dvec3 axis{0.0}, tangent{0.0}, bitangent{0.0};
  double light_radius = 0;  // of the light's disk on the plane at unit distance
  double z_min = 0;         // edges are clipped to this depth along the axis
  int32_t centre_count = 0;  // D at the centre, the visible triangle left out
  int64_t reach = 0;        // how far the edges can move any sample's count from the centre's
};

// An edge that changes samples of a pixel, and the blocks of samples its sector may hold.
struct PixelEdge {
  SampleEdge edge;
  SampleRuns runs;
};

// Per-thread scratch of one block of pixels.
struct Scratch {
  std::vector<FloatBlock> x, y;
  std::vector<IntBlock> count;
  std::vector<uint8_t> into;
  PixelBlock block;
  PixelFrame frames[kBlockPixels];
  int px[kBlockPixels], py[kBlockPixels];
  std::vector<PixelEdge> edges[kBlockPixels];
  std::vector<const CuttingTriangle*> cutting[kBlockPixels];
  explicit Scratch(const SampleSet& s)
      : x(s.padded / kSampleBlock), y(s.padded / kSampleBlock), count(s.padded / kSampleBlock),
        into(size_t(s.n)) {}
};

struct TileWork {
  uint64_t reads = 0;   // pixels set up
  uint64_t tests = 0;   // (pixel, edge) pairs given to the quick reject
  uint64_t exact = 0;   // of those, pairs tested exactly
  uint64_t inside = 0;  // of those, edges that changed samples
};

class ExactSoftShadows final : public PreparedTechnique {
 public:
  ExactSoftShadows(const ExactOptions& options, const Scene& scene)
      : options_(options), scene_(scene), samples_(makeSampleSet(options.samples, options.seed)) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  float finishPixel(const PixelFrame& f, const std::vector<PixelEdge>& edges,
                    const std::vector<const CuttingTriangle*>& cutting, const Light& light,
                    bool simd, Scratch& scratch) const;

  ExactOptions options_;
  const Scene& scene_;
  SampleSet samples_;
};

// The oracle shortens its shadow rays by this much so the light point itself never blocks
// (reference_technique.cpp).
constexpr double kTfarShrink = 1e-6;

// Does o + t d, 0 < t < t_max, cross the triangle (Moller and Trumbore 1997, in double)?
bool segmentHitsTriangle(const dvec3& o, const dvec3& d, double t_max, const CuttingTriangle& t) {
  const dvec3 e1 = t.v[1] - t.v[0], e2 = t.v[2] - t.v[0];
  const dvec3 q = glm::cross(d, e2);
  const double det = glm::dot(e1, q);
  if (det == 0.0) return false;  // the segment lies in the triangle's plane: crosses nothing
  const double inv = 1.0 / det;
  const dvec3 s = o - t.v[0];
  const double u = glm::dot(s, q) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const dvec3 r = glm::cross(s, e1);
  const double v = glm::dot(d, r) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double hit = glm::dot(e2, r) * inv;
  return hit > 0.0 && hit < t_max;
}

// Per scene triangle, decided once per light and remembered (as FacingAway): is the whole light
// strictly in front of it, on the side the eye sees, by more than the margin finishPixel uses
// to look for samples behind the surface? For such a pixel RayStart::intoSurface is false for
// the centre and every sample whatever the origin, so a pixel that no edge reaches is lit
// exactly when the stencil is 0, and needs no ray origin at all.
class ClearOfLight {
 public:
  ClearOfLight(const Scene& scene, const Light& light, const View& view)
      : scene_(&scene), eye_(view.eye), centre_(light.center), radius_(light.radius),
        known_(scene.triangleCount()) {}
  bool operator()(uint32_t primitive) const {
    const uint8_t known = known_[primitive].load(std::memory_order_relaxed);
    if (known != kUnknown) return known == kClear;
    const auto [m, t] = scene_->locateTriangle(primitive);
    const Mesh& mesh = scene_->meshes[m];
    const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
    dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    const double eye_side = glm::dot(n, eye_ - a);
    bool clear = false;
    if (length > 0.0 && eye_side != 0.0 && std::isfinite(eye_side)) {
      if (eye_side < 0.0) n = -n;
      clear = glm::dot(n, centre_ - a) / length > radius_ * (1.0 + 1e-4);
    }
    known_[primitive].store(clear ? kClear : kNotClear, std::memory_order_relaxed);
    return clear;
  }

 private:
  static constexpr uint8_t kUnknown = 0, kClear = 1, kNotClear = 2;
  const Scene* scene_;
  dvec3 eye_, centre_;
  double radius_;
  mutable std::vector<std::atomic<uint8_t>> known_;
};

// Sets up the frame of a pixel; false when its visibility is already known (`known`).
bool setupPixel(int x, int y, float depth, uint32_t primitive, int32_t stencil,
                const RayOrigins& origins, const Light& light, PixelFrame& f, float& known) {
  const dvec3 c(light.center);
  const double r = light.radius;
  f.ready = true;
  f.primitive = primitive;
  f.start = origins.start(x, y, depth, primitive);
  // A point inside the light sees all of it (as the oracle has it).
  if (glm::length(c - f.start.origin) <= r) {
    known = 1.0f;
    return false;
  }
  // The oracle's rays start at the float origin; every test here is made from that point.
  f.p = dvec3(vec3(f.start.origin));
  f.cone = makeSphereCone(f.start.origin, c, r);
  f.axis = dvec3(f.cone.axis);
  f.tangent = dvec3(f.cone.tangent);
  f.bitangent = dvec3(f.cone.bitangent);
  const double omc = f.cone.one_minus_cos_max;
  f.light_radius = std::sqrt(omc * (2.0 - omc)) / (1.0 - omc) * (1.0 + 1e-5);
  f.z_min = 1e-7 * glm::length(c - f.p);
  // The stencil counted the visible triangle exactly when the centre is behind it.
  f.centre_count = stencil - (f.start.intoSurface(c) ? 1 : 0);
  f.reach = 0;
  return true;
}

// The exact test of one edge at one point: false when the edge changes none of its samples,
// else `out` says which samples it changes and by how much.
bool edgeAtPixel(const PotentialEdge& e, const EdgeTriangle* triangles, const PixelFrame& f,
                 const SampleSet& samples, PixelEdge& pixel_edge, int32_t& weight_out) {
  SampleEdge& out = pixel_edge.edge;
  const dvec3& p = f.p;
  dvec3 a = e.a - p, b = e.b - p;
  double za = glm::dot(a, f.axis), zb = glm::dot(b, f.axis);
  if (za <= f.z_min && zb <= f.z_min) return false;  // behind the point: no ray toward the light
  // Silhouette from p: the signed number of the edge's triangles on each side of the plane
  // through p and the edge, from each triangle's own plane (EdgeTriangle). Left out: the
  // visible triangle, and triangles whose plane has p and the light centre on one side (no
  // segment from p to the light crosses them while the plane misses the light; the stencil
  // does not count them at the centre either).
  int32_t weight = 0;
  for (uint32_t k = 0; k < e.triangle_count; ++k) {
    const EdgeTriangle& t = triangles[e.first_triangle + k];
    if (t.id == f.primitive) continue;
    const double at_p = glm::dot(t.normal, p) + t.offset;
    if ((at_p > 0.0) == t.light_above) continue;
    weight -= t.winding * ((at_p > 0.0) - (at_p < 0.0));
  }
  if (weight == 0) return false;
  // Clip to z >= z_min: the part behind projects outside the light.
  if (za < f.z_min) {
    a += (b - a) * ((f.z_min - za) / (zb - za));
    za = f.z_min;
  } else if (zb < f.z_min) {
    b += (a - b) * ((f.z_min - zb) / (za - zb));
    zb = f.z_min;
  }
  const dvec2 a2(glm::dot(a, f.tangent) / za, glm::dot(a, f.bitangent) / za);
  const dvec2 b2(glm::dot(b, f.tangent) / zb, glm::dot(b, f.bitangent) / zb);
  // Distance from the centre (0, 0) to the projected segment: beyond the light, no sample.
  const dvec2 ab = b2 - a2;
  const double ab2 = glm::dot(ab, ab);
  const double t = ab2 > 0.0 ? std::clamp(-glm::dot(a2, ab) / ab2, 0.0, 1.0) : 0.0;
  if (glm::length(a2 + t * ab) > f.light_radius) return false;
  // Sector lines through the centre and each projected end: n_a = axis x a gives the value
  // -a.B x + a.T y, up to the positive factor 1 / z_a. Normalised in double, then rounded,
  // the same way for every edge sharing the end, so the half-open rule is watertight.
  auto sectorLine = [&f](const dvec3& v, float line[2]) {
    const double s = -glm::dot(v, f.bitangent), u = glm::dot(v, f.tangent);
    const double scale = std::max(std::fabs(s), std::fabs(u));
    line[0] = float(s / scale);
    line[1] = float(u / scale);
    return dvec2(s / scale, u / scale);
  };
  const dvec2 la = sectorLine(a, out.sector_a);
  const dvec2 lb = sectorLine(b, out.sector_b);
  const double a_at_b = la.x * b2.x + la.y * b2.y;
  const double b_at_a = lb.x * a2.x + lb.y * a2.y;
  if (a_at_b == 0.0 || b_at_a == 0.0) return false;  // the centre on the edge's line: a tie
  out.a_side = a_at_b > 0.0;
  out.b_side = b_at_a > 0.0;
  // The edge's line: the plane through p and the edge, n . (T x + B y + axis).
  const dvec3 n = glm::cross(a, b);
  const dvec3 l(glm::dot(n, f.tangent), glm::dot(n, f.bitangent), glm::dot(n, f.axis));
  const double l_scale = std::max({std::fabs(l.x), std::fabs(l.y), std::fabs(l.z)});
  out.line[0] = float(l.x / l_scale);
  out.line[1] = float(l.y / l_scale);
  out.line[2] = float(l.z / l_scale);
  out.centre_side = out.line[2] >= 0.0f;
  // Crossing from the centre's side onto the other: the triangles on that side (+1 each) are
  // entered, those on the centre's side (-1 each) left.
  out.delta = out.centre_side ? -weight : weight;
  weight_out = weight;
  // The sector's angles: the shorter way round from one projected end to the other.
  const double angle_a = pseudoAngle(a2.x, a2.y), angle_b = pseudoAngle(b2.x, b2.y);
  double turn = angle_b - angle_a;
  if (turn > 2.0) turn -= 4.0;
  if (turn <= -2.0) turn += 4.0;
  pixel_edge.runs = turn >= 0.0 ? sampleRuns(samples, angle_a, angle_a + turn)
                                : sampleRuns(samples, angle_b, angle_b - turn);
  return true;
}

float ExactSoftShadows::finishPixel(const PixelFrame& f, const std::vector<PixelEdge>& edges,
                                    const std::vector<const CuttingTriangle*>& cutting,
                                    const Light& light, bool simd, Scratch& scratch) const {
  if (!f.ready) return f.stencil == 0 ? 1.0f : 0.0f;  // ClearOfLight, and no edge
  const dvec3 c(light.center);
  const double r = light.radius;
  const int n = samples_.n;
  // Samples behind the visible triangle's plane are blocked by it; only where the light
  // reaches across that plane does any sample need the test (the oracle's, sample by sample).
  int into_count = 0;
  bool any_into = false;
  const double normal_length = glm::length(f.start.plane_normal);
  if (normal_length > 0.0 &&
      glm::dot(f.start.plane_normal, c - f.start.plane_point) / normal_length <=
          r * (1.0 + 1e-4)) {
    any_into = true;
    for (int i = 0; i < n; ++i) {
      const ConeSample s = sampleSphereCone(f.cone, samples_.disk[size_t(i)]);
      const bool into =
          f.start.intoSurface(f.start.origin + dvec3(s.direction) * double(s.distance));
      scratch.into[size_t(i)] = into;
      into_count += into;
    }
  }
  if (edges.empty() && cutting.empty())
    return f.centre_count == 0 ? float(n - into_count) / float(n) : 0.0f;
  // No sample's count can come down to 0 (cutting triangles only add).
  if (f.centre_count > f.reach) return 0.0f;

  // Sample positions on the plane at unit distance (sampleSphereCone's angles, in float).
  float* sx = scratch.x.data()->v;
  float* sy = scratch.y.data()->v;
  int32_t* count = scratch.count.data()->v;
  samplePositions(samples_.radius2.data(), samples_.cos_phi.data(), samples_.sin_phi.data(),
                  f.cone.one_minus_cos_max, sx, sy, samples_.padded, simd);
  std::fill(count, count + samples_.padded, f.centre_count);
  for (const PixelEdge& e : edges) {
    for (int k = 0; k < 2; ++k) {
      const uint32_t b = e.runs.begin[k];
      if (e.runs.end[k] > b)
        addEdgeCrossings(e.edge, sx + b, sy + b, count + b, e.runs.end[k] - b, simd);
    }
  }
  // Triangles cutting the light, against each sample's segment as the oracle traces it.
  if (!cutting.empty()) {
    for (int i = 0; i < n; ++i) {
      if (count[i] != 0) continue;  // blocked already
      const ConeSample s = sampleSphereCone(f.cone, samples_.disk[size_t(i)]);
      const double t_max = double(s.distance) * (1.0 - kTfarShrink);
      for (const CuttingTriangle* t : cutting) {
        if (segmentHitsTriangle(f.p, dvec3(s.direction), t_max, *t)) {
          ++count[i];
          break;
        }
      }
    }
  }
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
    const ClearOfLight clear(scene_, light, view);
    const size_t tiles = size_t(bins.columns) * size_t(bins.rows);
    const int tile = 1 << bins.level;
    std::vector<TileWork> tile_work(tiles);
    ProgressBar progress("exact", tiles, context.show_progress);
    parallelFor(tiles, [&](size_t index) {
      thread_local std::unique_ptr<Scratch> scratch_slot;
      if (!scratch_slot || scratch_slot->into.size() != size_t(samples_.n))
        scratch_slot = std::make_unique<Scratch>(samples_);
      Scratch& scratch = *scratch_slot;
      TileWork& work = tile_work[index];
      const int tx = int(index % size_t(bins.columns)), ty = int(index / size_t(bins.columns));
      const uint32_t* begin = bins.edges.data() + bins.begin[index];
      const uint32_t* end = bins.edges.data() + bins.begin[index + 1];
      const int x0 = tx * tile, x1 = std::min(width, x0 + tile);
      const int y0 = ty * tile, y1 = std::min(height, y0 + tile);
      // Blocks of up to 64 pixels, row after row of the tile.
      int x = x0, y = y0;
      while (y < y1) {
        PixelBlock& block = scratch.block;
        block.active = 0;
        int used = 0;
        for (; y < y1 && used < kBlockPixels; x = (x + 1 < x1) ? x + 1 : x0, y += (x == x0)) {
          const int i = used++;
          scratch.px[i] = x;
          scratch.py[i] = y;
          block.sx[i] = float(x) + 0.5f;
          block.sy[i] = float(y) + 0.5f;
          block.z[i] = eye.depth.depth.at(x, y);
          const uint32_t id = eye.primitive.at(x, y);
          if (!(block.z[i] > 0.0f) || id == kNoPrimitive || away(id)) continue;
          ++work.reads;
          PixelFrame& f = scratch.frames[i];
          f.ready = false;
          f.stencil = stencil.at(x, y);
          f.primitive = id;
          if (!clear(id)) {
            float known = 0.0f;
            if (!setupPixel(x, y, block.z[i], id, f.stencil, origins, light, f, known)) {
              soft.at(x, y) = known;
              continue;
            }
          }
          block.active |= uint64_t(1) << i;
          scratch.edges[i].clear();
        }
        for (; used < kBlockPixels; ++used) block.z[used] = 0.0f;
        if (block.active == 0) continue;
        for (const uint32_t* it = begin; it != end; ++it) {
          work.tests += uint64_t(__builtin_popcountll(block.active));
          uint64_t candidates = edgeCandidates(bins.tests[*it], block, context.simd);
          while (candidates != 0) {
            const int i = __builtin_ctzll(candidates);
            candidates &= candidates - 1;
            ++work.exact;
            PixelEdge pixel_edge;
            int32_t weight = 0;
            PixelFrame& f = scratch.frames[i];
            if (!f.ready) {
              float known = 0.0f;  // never set: a clear pixel is outside the light
              setupPixel(scratch.px[i], scratch.py[i], block.z[i], f.primitive, f.stencil,
                         origins, light, f, known);
            }
            if (!edgeAtPixel(edges.edges[*it], edges.triangles.data(), f, samples_, pixel_edge,
                             weight))
              continue;
            scratch.edges[i].push_back(pixel_edge);
            f.reach += std::abs(weight);
            ++work.inside;
          }
        }
        // Triangles cutting the light: every pixel of the tile takes them, less the centre
        // segment's crossings, which the stencil counted.
        const uint32_t* cut_begin = bins.cutting.data() + bins.cutting_begin[index];
        const uint32_t* cut_end = bins.cutting.data() + bins.cutting_begin[index + 1];
        for (uint64_t active = block.active; active != 0; active &= active - 1) {
          const int i = __builtin_ctzll(active);
          scratch.cutting[i].clear();
          PixelFrame& f = scratch.frames[i];
          for (const uint32_t* it = cut_begin; it != cut_end; ++it) {
            const CuttingTriangle& t = edges.cutting[*it];
            if (t.id == f.primitive) continue;
            if (!f.ready) {
              float known = 0.0f;  // never set: a clear pixel is outside the light
              setupPixel(scratch.px[i], scratch.py[i], block.z[i], f.primitive, f.stencil,
                         origins, light, f, known);
            }
            if (segmentHitsTriangle(f.p, dvec3(light.center) - f.p, 1.0 - kTfarShrink, t))
              --f.centre_count;
            scratch.cutting[i].push_back(&t);
          }
          soft.at(scratch.px[i], scratch.py[i]) = finishPixel(
              f, scratch.edges[i], scratch.cutting[i], light, context.simd, scratch);
        }
      }
      progress.add();
    });
    progress.finish();
    for (const TileWork& w : tile_work) {
      stats.z_reads += w.reads;
      stats.penumbra_tests += w.exact;
      stats.penumbra_inside += w.inside;
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
