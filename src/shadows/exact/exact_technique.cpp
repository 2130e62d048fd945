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
// The steps, in render's order: stencilAndEdges (the stencil at the centre beside the potential
// edges and their tiles), then per tile (shadeTile) and block of 64 pixels: readBlock (the
// stencil and each pixel's basis), testEdges and testEdgeAt (the quick reject, the count moved
// to the shaded point, the exact test of each edge), collectCuttingTriangles, finishPixel (the
// sums over the samples).
//
// The visible triangle itself is left out of every count: a sample behind its plane is blocked
// (the oracle decides the same, RayStart::intoSurface), and the stencil counted it exactly when
// the light centre is behind it.
#include "shadows/exact/exact_technique.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/timer.h"
#include "shadows/exact/light_samples.h"
#include "shadows/exact/pixel_edges.h"
#include "shadows/exact/sample_kernel.h"
#include "shadows/exact/vertex_rings.h"
#include "shadows/shared_options.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/caster_culling/culled_edges.h"
#include "shadows/stages/light_sampling/light_sampling.h"
#include "shadows/stages/light_sampling/ray_origin.h"
#include "shadows/stages/potential_edges/edge_bins.h"
#include "shadows/stages/potential_edges/edge_screen_test.h"
#include "shadows/stages/potential_edges/potential_edges.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/stages/silhouettes/silhouette.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace {

constexpr int kMaxSamples = 4096;

struct alignas(kSampleAlignment) FloatBlock {
  float v[kSampleBlock];
};
struct alignas(kSampleAlignment) IntBlock {
  int32_t v[kSampleBlock];
};

// Per-thread scratch of one block of pixels.
struct ExactScratch {
  std::vector<FloatBlock> x, y;
  std::vector<IntBlock> count;
  std::vector<uint8_t> into;
  std::vector<uint8_t> lit, lit_in_order;  // per sample, sorted and in the oracle's order
  std::vector<ConeSample> cone_samples;  // a pixel's samples, for the triangles cutting the light
  PixelBlock block;
  PixelBasis frames[kBlockPixels];
  int px[kBlockPixels], py[kBlockPixels];
  std::vector<PixelEdge> edges[kBlockPixels];
  std::vector<const CuttingTriangle*> cutting[kBlockPixels];
  OriginTriangle origin_triangle;  // the last visible triangle set up (RayOrigins::start)
  std::vector<uint32_t> neighbours;  // of the visible triangle (VertexRings)
  PixelLanes pixel_lanes;             // one edge's candidate pixels (edgeAtPixels)
  EdgeLanes edge_lanes;
  explicit ExactScratch(const SortedSamples& s)
      : x(s.padded / kSampleBlock), y(s.padded / kSampleBlock), count(s.padded / kSampleBlock),
        into(size_t(s.n)), lit(size_t(s.n)), lit_in_order(size_t(s.n)),
        cone_samples(size_t(s.n)) {}
};

struct ExactTileWork {
  uint64_t reads = 0;   // pixels set up
  uint64_t tests = 0;   // (pixel, edge) pairs given to the quick reject
  uint64_t exact = 0;   // of those, pairs tested exactly
  uint64_t inside = 0;  // of those, edges that changed samples
};

// The light's samples as the oracle traces them toward a disk or rectangle light: fixed points
// of its area (planarLightPoint), in the sorted order, and for a textured light what each one
// emits (light.h). Empty `points` for a sphere, whose samples follow each point's cone.
struct PlanarSamples {
  std::vector<dvec3> points;
  std::vector<vec3> texels;  // textured lights only, in the oracle's sample order
  dvec3 texel_sum{0.0};      // summed in that order, as the oracle does
};

PlanarSamples planarSamples(const Light& light, const SortedSamples& samples) {
  PlanarSamples planar;
  if (light.shape == LightShape::Sphere) return planar;
  for (const vec2& u : samples.square) planar.points.push_back(planarLightPoint(light, u));
  if (light.texture != nullptr) {
    planar.texels.resize(size_t(samples.n));
    for (int i = 0; i < samples.n; ++i) {
      const vec3 texel = light.texture->at(samples.square[size_t(i)]);
      planar.texels[samples.order[size_t(i)]] = texel;
    }
    for (const vec3& t : planar.texels) planar.texel_sum += dvec3(t);
  }
  return planar;
}

// Everything one light's pass over the tiles reads (Laine et al. 2005, section 3: per point,
// the reference count at the light centre plus the sums of the edges seen as silhouettes).
struct LightPass {
  const Light& light;
  const View& view;
  const EyeBuffers& eye;
  const RenderContext& context;
  const Image<int32_t>& stencil;  // D at the centre, at each depth-buffer point
  const PotentialEdges& edges;
  const EdgeBins& bins;
  const StencilQuads& quads;
  const FacingAway& away;
  const RayOrigins& origins;
  const PlanarSamples& planar;
  QuadReplay replay;
  dvec3 light_centre, eye_position;
  dmat4 view_projection;
  double pixel_angle;  // a pixel footprint at unit distance, at the image centre (ray_origin.h)
  Image<float>& soft;
  ChannelVisibility& soft_rgb;  // a textured light's, else empty

  void store(int x, int y, float grey, const vec3& rgb) const {
    soft.at(x, y) = grey;
    if (!soft_rgb[0].empty()) {
      for (int ch = 0; ch < 3; ++ch) soft_rgb[size_t(ch)].at(x, y) = rgb[ch];
    }
  }
};

class ExactSoftShadows final : public PreparedTechnique {
 public:
  ExactSoftShadows(const ExactOptions& options, const Scene& scene)
      : options_(options), scene_(scene), bounds_(scene.bounds()),
        samples_(makeSampleSet(options.samples, options.seed)), rings_(scene),
        geometry_(edgeGeometry(scene)) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  float finishPixel(const PixelBasis& f, const std::vector<PixelEdge>& edges,
                    const std::vector<const CuttingTriangle*>& cutting, const Light& light,
                    const PlanarSamples& planar, bool simd, ExactScratch& scratch,
                    vec3& rgb) const;
  int samplesIntoSurface(const PixelBasis& f, const Light& light, const PlanarSamples& planar,
                         ExactScratch& scratch) const;
  void addEdgeSums(const PixelBasis& f, const std::vector<PixelEdge>& edges,
                   const PlanarSamples& planar, bool simd, int32_t* count,
                   ExactScratch& scratch) const;
  void addCuttingTriangles(const PixelBasis& f, const std::vector<const CuttingTriangle*>& cutting,
                           const PlanarSamples& planar, int32_t* count,
                           ExactScratch& scratch) const;
  // The steps of one light's pass (render): the stencil and the binned edges, then per tile
  // and block of pixels the set-up, the edges' and cutting triangles' tests and the count.
  void stencilAndEdges(const Light& light, const View& view, const EyeBuffers& eye,
                       const RenderContext& context, const CasterCulling& culling,
                       StencilQuads& quads,
                       Image<int32_t>& stencil, std::shared_ptr<const PotentialEdges>& edges,
                       EdgeBins& bins, TechniqueResult& result) const;
  void shadeTiles(const LightPass& pass, Stats& stats) const;
  void shadeTile(const LightPass& pass, size_t index, ExactScratch& scratch,
                 ExactTileWork& work) const;
  void readBlock(const LightPass& pass, const EdgeBinTile& bin, int& x, int& y,
                 ExactScratch& scratch, ExactTileWork& work) const;
  bool replayed(const LightPass& pass, uint32_t primitive) const;
  bool setUpPixel(const LightPass& pass, int i, ExactScratch& scratch, float& known) const;
  void setUpIfClear(const LightPass& pass, int i, ExactScratch& scratch) const;
  void cuttingTestInputs(const LightPass& pass, ExactScratch& scratch) const;
  void testEdges(const LightPass& pass, const EdgeBinTile& bin, ExactScratch& scratch,
                 ExactTileWork& work) const;
  void testEdgeAt(const LightPass& pass, const PotentialEdge& edge, uint64_t candidates,
                  ExactScratch& scratch, ExactTileWork& work) const;
  void collectCuttingTriangles(const LightPass& pass, size_t index, ExactScratch& scratch) const;
  // The visibility of the samples marked lit in scratch.lit.
  float tally(const PlanarSamples& planar, ExactScratch& scratch, vec3& rgb) const;
  float insideLightPixel(const PixelBasis& f, const PlanarSamples& planar,
                         ExactScratch& scratch, vec3& rgb) const;

  // The potential edges of a light at `centre` and `radius` (potentialEdges: they depend on
  // nothing else), kept while the light does not move: a warm frame under a still light skips
  // them. Up to kEdgeCacheLights lights, the least recently used replaced.
  std::shared_ptr<const PotentialEdges> cachedPotentialEdges(const Light& light) const;
  // The meshes' silhouettes from the light centre (the stencil's two-sided casters) kept beside
  // its potential edges: null until a frame under that light has found them (keepSilhouettes).
  std::shared_ptr<const std::vector<Silhouette>> cachedSilhouettes(const Light& light) const;
  void keepSilhouettes(const Light& light, std::vector<Silhouette> silhouettes) const;
  struct EdgeCacheEntry {
    vec3 centre{0.0f};
    float radius = 0.0f;
    uint64_t used = 0;
    std::shared_ptr<const PotentialEdges> edges;
    std::shared_ptr<const std::vector<Silhouette>> silhouettes;
  };
  static constexpr size_t kEdgeCacheLights = 8;
  mutable std::mutex edge_cache_mutex_;
  mutable std::vector<EdgeCacheEntry> edge_cache_;
  mutable uint64_t edge_cache_clock_ = 0;

  ExactOptions options_;
  const Scene& scene_;
  Bounds3 bounds_;  // of every visible point (binEdges)
  SortedSamples samples_;
  VertexRings rings_;
  EdgeGeometry geometry_;  // the potential edges' light-independent half
};

// Samples behind the visible triangle's plane are blocked by it (scratch.into); only where the
// light reaches across that plane does any sample need the test (the oracle's, sample by
// sample); the margin is FacingAway's, which lets pixels no edge reaches skip all of this.
// Returns how many are blocked so, or -1 when the plane leaves the whole light in front.
int ExactSoftShadows::samplesIntoSurface(const PixelBasis& f, const Light& light,
                                         const PlanarSamples& planar,
                                         ExactScratch& scratch) const {
  const double normal_length = glm::length(f.start.plane_normal);
  const double r = light.radius;
  if (!(normal_length > 0.0 &&
        glm::dot(f.start.plane_normal, dvec3(light.center) - f.start.plane_point) / normal_length <=
            r * (1.0 + FacingAway::kClearMargin)))
    return -1;
  // Where sample i lies in the world: the planar light's fixed point, or on the cone's cap of a
  // sphere light. The two cases in loops of their own, and the flags through a local pointer:
  // one loop calling a function for both reloaded the vector's data and re-tested the light's
  // shape for every sample.
  const int n = samples_.n;
  uint8_t* into = scratch.into.data();
  if (!planar.points.empty()) {
    for (int i = 0; i < n; ++i) into[i] = f.start.intoSurface(planar.points[size_t(i)]);
  } else {
    for (int i = 0; i < n; ++i) {
      const ConeSample c = sampleSphereCone(f.cone, samples_.disk[size_t(i)]);
      into[i] = f.start.intoSurface(f.start.origin + dvec3(c.direction) * double(c.distance));
    }
  }
  int into_count = 0;
  for (int i = 0; i < n; ++i) into_count += into[i];
  return into_count;
}

// The edges' sums (Laine et al. 2005, section 3): each edge adds its delta to the samples its
// projection separates from the centre, on the plane at unit distance.
void ExactSoftShadows::addEdgeSums(const PixelBasis& f, const std::vector<PixelEdge>& edges,
                                   const PlanarSamples& planar, bool simd, int32_t* count,
                                   ExactScratch& scratch) const {
  // Sample positions on the plane at unit distance: sampleSphereCone's angles in float, or the
  // planar light's points projected from the point.
  const int n = samples_.n;
  float* sx = scratch.x.data()->v;
  float* sy = scratch.y.data()->v;
  const bool is_planar = !planar.points.empty();
  if (is_planar) {
    for (int i = 0; i < n; ++i) {
      const dvec3 v = planar.points[size_t(i)] - f.p;
      const double z = glm::dot(v, f.axis);
      sx[i] = float(glm::dot(v, f.tangent) / z);
      sy[i] = float(glm::dot(v, f.bitangent) / z);
    }
    // Padding at the centre, on its side of every edge: never counted.
    std::fill(sx + n, sx + samples_.padded, 0.0f);
    std::fill(sy + n, sy + samples_.padded, 0.0f);
  } else {
    samplePositions(samples_.radius2.data(), samples_.cos_phi.data(), samples_.sin_phi.data(),
                    f.cone.one_minus_cos_max, sx, sy, samples_.padded, simd);
  }
  for (const PixelEdge& e : edges) {
    // A planar light's samples keep no angle around the centre: every block is visited.
    if (is_planar) {
      addEdgeCrossings(e.edge, sx, sy, count, samples_.padded, simd);
      continue;
    }
    for (int k = 0; k < 2; ++k) {
      const uint32_t b = e.runs.begin[k];
      if (e.runs.end[k] > b)
        addEdgeCrossings(e.edge, sx + b, sy + b, count + b, e.runs.end[k] - b, simd);
    }
  }
}

// Triangles cutting the light, against each sample's segment as the oracle traces it: the
// samples of the blocks the triangle's angular extent can reach and not blocked already.
void ExactSoftShadows::addCuttingTriangles(const PixelBasis& f,
                                           const std::vector<const CuttingTriangle*>& cutting,
                                           const PlanarSamples& planar, int32_t* count,
                                           ExactScratch& scratch) const {
  const int n = samples_.n;
  const bool is_planar = !planar.points.empty();
  if (!is_planar) {
    for (int i = 0; i < n; ++i)
      scratch.cone_samples[size_t(i)] = sampleSphereCone(f.cone, samples_.disk[size_t(i)]);
  }
  for (const CuttingTriangle* t : cutting) {
    const SampleRuns runs = triangleRuns(*t, f, samples_);
    for (int k = 0; k < 2; ++k) {
      for (uint32_t i = runs.begin[k]; i < std::min(runs.end[k], uint32_t(n)); ++i) {
        if (count[i] != 0) continue;
        if (is_planar) {
          if (segmentHitsTriangle(f.p, planar.points[i] - f.p, 1.0 - kTfarShrink, *t))
            count[i] = 1;
          continue;
        }
        const ConeSample& s = scratch.cone_samples[i];
        const double t_max = double(s.distance) * (1.0 - kTfarShrink);
        if (segmentHitsTriangle(f.p, dvec3(s.direction), t_max, *t)) count[i] = 1;
      }
    }
  }
}

float ExactSoftShadows::finishPixel(const PixelBasis& f, const std::vector<PixelEdge>& edges,
                                    const std::vector<const CuttingTriangle*>& cutting,
                                    const Light& light, const PlanarSamples& planar, bool simd,
                                    ExactScratch& scratch, vec3& rgb) const {
  // The count at the centre is a number of triangles crossed, never below 0: a negative
  // stencil, or the visible triangle taken out of a stencil that did not count it (its own
  // quads rasterized past a pixel whose depth-buffer point lies just off it), is rounding of
  // the raster passes, and the count is 0 there.
  if (!f.ready) {  // clear of the light, and no edge
    const float v = f.stencil <= 0 ? 1.0f : 0.0f;
    rgb = vec3(v);
    return v;
  }
  const int32_t centre_count = std::max(f.centre_count, 0);
  // No sample's count can come down to 0 (the edges move it by at most `reach`, cutting
  // triangles only add): every sample is blocked, whichever side of the visible triangle's
  // plane it lies on, so the umbra skips the test below.
  if (centre_count > f.reach) {
    rgb = vec3(0.0f);
    return 0.0f;
  }
  const int n = samples_.n;
  const int into_count = samplesIntoSurface(f, light, planar, scratch);
  const bool any_into = into_count >= 0;
  // No edge and no cutting triangle: reach 0, and centre_count 0 by the test above.
  if (edges.empty() && cutting.empty() && planar.texels.empty()) {
    const float v = float(n - std::max(into_count, 0)) / float(n);
    rgb = vec3(v);
    return v;
  }
  int32_t* count = scratch.count.data()->v;
  std::fill(count, count + samples_.padded, centre_count);
  if (!edges.empty() || !cutting.empty()) addEdgeSums(f, edges, planar, simd, count, scratch);
  if (!cutting.empty()) addCuttingTriangles(f, cutting, planar, count, scratch);
  if (planar.texels.empty()) {
    // One visibility for every channel: the lit samples counted in the same loop, without a
    // branch per sample (the short-circuit form compiled to one and was a fifth of the tile
    // loop's own time on `spheres`).
    int lit = 0;
    if (any_into) {
      const uint8_t* into = scratch.into.data();
      for (int i = 0; i < n; ++i) lit += int(count[i] == 0) & int(into[i] == 0);
    } else {
      for (int i = 0; i < n; ++i) lit += int(count[i] == 0);
    }
    const float v = float(lit) / float(n);
    rgb = vec3(v);
    return v;
  }
  for (int i = 0; i < n; ++i)
    scratch.lit[size_t(i)] = count[i] == 0 && !(any_into && scratch.into[size_t(i)]);
  return tally(planar, scratch, rgb);
}

float ExactSoftShadows::tally(const PlanarSamples& planar, ExactScratch& scratch,
                              vec3& rgb) const {
  const int n = samples_.n;
  int lit = 0;
  for (int i = 0; i < n; ++i) lit += scratch.lit[size_t(i)];
  const float grey = float(lit) / float(n);
  rgb = vec3(grey);
  if (!planar.texels.empty()) {
    // The oracle's per-channel weighting, summed in its sample order (reference_technique.cpp).
    for (int i = 0; i < n; ++i)
      scratch.lit_in_order[samples_.order[size_t(i)]] = scratch.lit[size_t(i)];
    dvec3 seen(0.0);
    for (int k = 0; k < n; ++k)
      if (scratch.lit_in_order[size_t(k)]) seen += dvec3(planar.texels[size_t(k)]);
    for (int ch = 0; ch < 3; ++ch)
      rgb[ch] = planar.texel_sum[ch] > 0.0 ? float(seen[ch] / planar.texel_sum[ch]) : 1.0f;
  }
  return grey;
}

float ExactSoftShadows::insideLightPixel(const PixelBasis& f, const PlanarSamples& planar,
                                         ExactScratch& scratch, vec3& rgb) const {
  // A point inside a planar light's bounding ball: no cone toward the light, so every sample's
  // segment is tested against every triangle but the visible one, as the oracle traces it.
  // Rare (a receiver closer to the light's centre than its radius) and slow.
  const int n = samples_.n;
  const dvec3 p(vec3(f.start.origin));  // the oracle's float origin
  for (int i = 0; i < n; ++i) {
    const dvec3& target = planar.points[size_t(i)];
    bool lit = glm::length(target - f.start.origin) > 0.0 && !f.start.intoSurface(target);
    uint32_t id = 0;
    for (const Mesh& mesh : scene_.meshes) {
      const size_t triangles = mesh.triangleCount();
      for (size_t t = 0; t < triangles && lit; ++t) {
        if (id + t == f.primitive) continue;
        lit = !segmentHitsTriangle(p, target - p, 1.0 - kTfarShrink, dvec3(mesh.vertex(t, 0)),
                                   dvec3(mesh.vertex(t, 1)), dvec3(mesh.vertex(t, 2)));
      }
      id += uint32_t(triangles);
    }
    scratch.lit[size_t(i)] = lit;
  }
  return tally(planar, scratch, rgb);
}

// The two-sided stencil at the light centre (the reference count D(c)) and the potential
// silhouette edges binned to tiles depend only on the eye buffers: they run at once (their
// counters and timings kept apart, then added). The edge side's passes are marked concurrent
// (Stats: kConcurrentPass), so the light's total stays the time it took.
std::shared_ptr<const PotentialEdges> ExactSoftShadows::cachedPotentialEdges(
    const Light& light) const {
  {
    const std::lock_guard<std::mutex> lock(edge_cache_mutex_);
    for (EdgeCacheEntry& entry : edge_cache_) {
      // Bit-equal floats: the same light, the same edges.
      if (entry.centre == light.center && entry.radius == light.radius) {
        entry.used = ++edge_cache_clock_;
        return entry.edges;
      }
    }
  }
  auto edges = std::make_shared<const PotentialEdges>(potentialEdges(scene_, geometry_, light));
  const std::lock_guard<std::mutex> lock(edge_cache_mutex_);
  EdgeCacheEntry entry{light.center, light.radius, ++edge_cache_clock_, edges, nullptr};
  if (edge_cache_.size() < kEdgeCacheLights) {
    edge_cache_.push_back(std::move(entry));
  } else {
    *std::min_element(edge_cache_.begin(), edge_cache_.end(),
                      [](const EdgeCacheEntry& a, const EdgeCacheEntry& b) {
                        return a.used < b.used;
                      }) = std::move(entry);
  }
  return edges;
}

std::shared_ptr<const std::vector<Silhouette>> ExactSoftShadows::cachedSilhouettes(
    const Light& light) const {
  const std::lock_guard<std::mutex> lock(edge_cache_mutex_);
  for (const EdgeCacheEntry& entry : edge_cache_)
    if (entry.centre == light.center && entry.radius == light.radius) return entry.silhouettes;
  return nullptr;
}

void ExactSoftShadows::keepSilhouettes(const Light& light,
                                       std::vector<Silhouette> silhouettes) const {
  auto kept = std::make_shared<const std::vector<Silhouette>>(std::move(silhouettes));
  const std::lock_guard<std::mutex> lock(edge_cache_mutex_);
  for (EdgeCacheEntry& entry : edge_cache_)
    if (entry.centre == light.center && entry.radius == light.radius && !entry.silhouettes)
      entry.silhouettes = std::move(kept);
}

void ExactSoftShadows::stencilAndEdges(const Light& light, const View& view, const EyeBuffers& eye,
                                       const RenderContext& context,
                                       const CasterCulling& culling, StencilQuads& quads,
                                       Image<int32_t>& stencil,
                                       std::shared_ptr<const PotentialEdges>& edges,
                                       EdgeBins& bins, TechniqueResult& result) const {
  Stats& stats = result.stats;
  ShadowStencilOptions stencil_options;
  stencil_options.simd = context.simd;
  // Two-sided casters: the stencil counts every triangle between the point and the centre.
  stencil_options.policy = CasterPolicy::TwoSided;
  stencil_options.skip_own_quads = true;
  stencil_options.quads = &quads;
  // The silhouettes from the centre depend on the light alone: found by the first frame under
  // it, kept with its potential edges.
  const std::shared_ptr<const std::vector<Silhouette>> known = cachedSilhouettes(light);
  std::vector<Silhouette> found;
  stencil_options.known_silhouettes = known.get();
  stencil_options.found_silhouettes = &found;
  stencil_options.caster_culling = &culling;
  if (context.debug_layers) stencil_options.debug_layers = &result.debug_layers;
  Stats edge_stats;
  const size_t passes_before = stats.time_ms.size();
  const auto start = std::chrono::steady_clock::now();
  parallelInvoke(
      [&] { stencil = shadowStencil(scene_, light.center, view, eye, stencil_options, stats); },
      [&] {
        {
          PassTimer timer(edge_stats, "edges");
          edges = cachedPotentialEdges(light);
          // Cached per light, culled per frame: the culled casters' edges leave a copy.
          if (!culling.may_shadow.empty())
            edges = std::make_shared<const PotentialEdges>(
                withoutCulledCasters(*edges, scene_, culling));
          edge_stats.wedges += edges->edges.size();
        }
        PassTimer timer(edge_stats, "binning");
        bins = binEdges(*edges, light, view, eye.depth, options_.tile_level,
                        kMaxOriginOffsetFootprints, bounds_, context.simd);
        edge_stats.tiles_tested += bins.tiles_tested;
        edge_stats.tiles_culled += bins.tiles_culled;
      });
  const double wall =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!known) keepSilhouettes(light, std::move(found));
  // The stencil's passes keep their times; the edge side's are marked concurrent (totalMs
  // leaves them out), and the wall time the section took beyond the stencil is its own pass, so
  // the frame's passes add up to its wall time with no negative entry.
  double stencil_ms = 0.0;
  for (size_t k = passes_before; k < stats.time_ms.size(); ++k)
    stencil_ms += stats.time_ms[k].second;
  for (auto& [name, ms] : edge_stats.time_ms) name += kConcurrentPass;
  stats.add(edge_stats);
  stats.time_ms.emplace_back(kConcurrentWait, std::max(0.0, wall - stencil_ms));
  // After the stencil: adding a layer moves the ones it draws into.
  if (context.debug_layers)
    addBinnedEdgeCounts(bins, debugLayer(result.debug_layers, kWedgeFootprintsLayer,
                                         "potential silhouette edges binned at the pixel's tile",
                                         view.width, view.height));
}

// Whether the visible triangle's mesh was drawn z-pass (its quads replayed, QuadReplay).
bool ExactSoftShadows::replayed(const LightPass& pass, uint32_t primitive) const {
  return !pass.replay.any_zfail || pass.quads.zfail[scene_.locateTriangle(primitive).first] == 0;
}

// The basis of the block's pixel i (setupPixel); on a z-pass volume with the caps of the
// visible triangle's neighbours its origin may lie behind (capCrossings). Its quick-reject
// offset becomes how far its shaded point lies from its depth-buffer point, over the point's w
// (PixelBlock::offset), rounded up: most points lie on the pixel's own ray, and the reject then
// keeps only the edges that can reach the point itself. Never above the offset the tiles were
// binned with.
bool ExactSoftShadows::setUpPixel(const LightPass& pass, int i, ExactScratch& scratch,
                                  float& known) const {
  PixelBlock& block = scratch.block;
  PixelBasis& f = scratch.frames[i];
  const uint32_t id = f.primitive;
  const bool z_pass = replayed(pass, id);
  if (!setupPixel(scratch.px[i], scratch.py[i], block.z[i], id, f.stencil, pass.origins,
                  pass.light, scratch.origin_triangle, z_pass, f, known))
    return false;
  const double apart = glm::length(f.p - f.start.depth_point);
  f.quad_reach = 4.0 * apart + 1e-6 * glm::length(f.p - pass.eye_position);
  const double w = (pass.view_projection * dvec4(f.start.depth_point, 1.0)).w;
  const double offset = apart / w * (1.0 + 1e-5);
  block.offset[i] = offset < double(pass.bins.offset) ? float(offset) * (1.0f + 1e-6f) + 1e-30f
                                                      : pass.bins.offset;
  // Only an origin near the triangle's border can hide behind a neighbour: the eye sees the
  // depth-buffer point, and a neighbour between the two rays comes within their distance of
  // the origin.
  const OriginTriangle& t = scratch.origin_triangle;
  double border = std::numeric_limits<double>::infinity();
  if (t.primitive == id) {
    const dvec3 corners[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) border = std::min(border, glm::dot(f.p - corners[k], t.inward[k]));
  }
  if (z_pass && border <= 8.0 * apart) {
    rings_.neighbours(id, scratch.neighbours);
    f.centre_count +=
        capCrossings(scene_, scratch.neighbours, f, pass.light_centre, pass.eye_position);
  }
  return true;
}

// A pixel clear of the light, set up once an edge may reach it.
void ExactSoftShadows::setUpIfClear(const LightPass& pass, int i, ExactScratch& scratch) const {
  float known = 0.0f;  // never set: a clear pixel is outside the light
  if (!scratch.frames[i].ready) setUpPixel(pass, i, scratch, known);
}

// The next block of up to 64 pixels of the tile, row after row from (x, y): each pixel's
// stencil, and the basis of those not clear of the light. Pixels whose visibility is known
// already are stored; the others are the block's active ones.
void ExactSoftShadows::readBlock(const LightPass& pass, const EdgeBinTile& bin, int& x, int& y,
                                 ExactScratch& scratch, ExactTileWork& work) const {
  PixelBlock& block = scratch.block;
  block.active = 0;
  std::fill(std::begin(block.offset), std::end(block.offset), pass.bins.offset);
  int used = 0;
  for (; y < bin.y1 && used < kBlockPixels;
       x = (x + 1 < bin.x1) ? x + 1 : bin.x0, y += (x == bin.x0)) {
    const int i = used++;
    scratch.px[i] = x;
    scratch.py[i] = y;
    block.sx[i] = float(x) + 0.5f;
    block.sy[i] = float(y) + 0.5f;
    block.z[i] = pass.eye.depth.depth.at(x, y);
    block.qx[i] = block.qy[i] = block.qz[i] = block.reach[i] = block.slack[i] = 0.0f;
    const uint32_t id = pass.eye.primitive.at(x, y);
    if (!(block.z[i] > 0.0f) || id == kNoPrimitive || pass.away(id)) continue;
    ++work.reads;
    PixelBasis& f = scratch.frames[i];
    f.ready = false;
    f.stencil = pass.stencil.at(x, y);
    f.primitive = id;
    if (!pass.away.clearOfLight(id)) {
      float known = 0.0f;
      if (!setUpPixel(pass, i, scratch, known)) {
        vec3 rgb(known);
        if (f.inside_light) known = insideLightPixel(f, pass.planar, scratch, rgb);
        pass.store(x, y, known, rgb);
        continue;
      }
    }
    block.active |= uint64_t(1) << i;
    scratch.edges[i].clear();
  }
  for (; used < kBlockPixels; ++used) block.z[used] = 0.0f;
}

// The cutting triangles' quick test (PixelBlock): q from the depth-buffer point, the shaded
// point within kMaxOriginOffsetFootprints footprints of it, and a relative eps of 1e-5 against
// the float rounding of q, the corners and the sums (some 1e-7 of |v'| |q|) and
// classifyCutting's own margins (1e-9 |q|^2).
void ExactSoftShadows::cuttingTestInputs(const LightPass& pass, ExactScratch& scratch) const {
  PixelBlock& block = scratch.block;
  for (uint64_t active = block.active; active != 0; active &= active - 1) {
    const int i = __builtin_ctzll(active);
    const dvec3 p0 = pass.view.unproject(scratch.px[i], scratch.py[i], block.z[i]);
    const dvec3 q = pass.light_centre - p0;
    const double q_length = glm::length(q);
    const double offset = kMaxOriginOffsetFootprints * pass.pixel_angle *
                          glm::length(p0 - pass.eye_position) * 1.01;
    constexpr double kEps = 1e-5;
    block.qx[i] = float(q.x);
    block.qy[i] = float(q.y);
    block.qz[i] = float(q.z);
    block.reach[i] =
        float((double(pass.light.radius) + kEps * q_length) * q_length * (1.0 + 1e-6));
    block.slack[i] = float((offset + kEps * q_length) * (1.0 + 1e-6));
  }
}

// The tile's edges against the block's pixels: the quick reject of 64 pixels at a time, then
// for the candidates of each edge the count at the centre moved to their shaded points and the
// exact test (testEdgeAt). Each pixel's edges stay in the order of the tile's list.
void ExactSoftShadows::testEdges(const LightPass& pass, const EdgeBinTile& bin,
                                 ExactScratch& scratch, ExactTileWork& work) const {
  const EdgeBins& bins = pass.bins;
  // The records of the edges a few places on are fetched while this one is tested: the quick
  // reject is bound by reading them (a tile's edges lie anywhere in the mesh).
  constexpr ptrdiff_t kAhead = 4;
  for (const uint32_t* it = bin.begin; it != bin.end; ++it) {
    if (bin.end - it > kAhead) {
      const char* ahead = reinterpret_cast<const char*>(&bins.tests[it[kAhead]]);
      for (size_t line = 0; line < kEdgeTestHotBytes; line += 64) __builtin_prefetch(ahead + line);
    }
    work.tests += uint64_t(__builtin_popcountll(scratch.block.active));
    const uint64_t candidates = edgeCandidates(bins.tests[*it], scratch.block, pass.context.simd);
    if (candidates != 0) testEdgeAt(pass, pass.edges.edges[*it], candidates, scratch, work);
  }
}

// One edge at its candidate pixels: their counts at the centre moved to their shaded points
// (quadCountShift, or centreCountShift on a z-fail volume), then the exact test kEdgeLanes
// pixels at a time (edgeAtPixels; the pixels it defers, edgeAtPixel). An edge that changes
// samples joins the pixel's list.
void ExactSoftShadows::testEdgeAt(const LightPass& pass, const PotentialEdge& edge,
                                  uint64_t candidates, ExactScratch& scratch,
                                  ExactTileWork& work) const {
  const EdgeTriangle* triangles = pass.edges.triangles.data();
  int pending[kBlockPixels];
  int pending_count = 0;
  while (candidates != 0) {
    const int i = __builtin_ctzll(candidates);
    candidates &= candidates - 1;
    ++work.exact;
    setUpIfClear(pass, i, scratch);
    PixelBasis& f = scratch.frames[i];
    bool zfail = false;
    f.centre_count += quadCountShift(edge, pass.replay, scratch.px[i], scratch.py[i], f, zfail);
    if (zfail)
      f.centre_count += centreCountShift(edge, triangles, f, pass.light_centre, pass.eye_position);
    pending[pending_count++] = i;
  }
  for (int first = 0; first < pending_count; first += kEdgeLanes) {
    PixelLanes& pixel_lanes = scratch.pixel_lanes;
    pixel_lanes.count = std::min(kEdgeLanes, pending_count - first);
    for (int k = 0; k < pixel_lanes.count; ++k)
      pixel_lanes.setLane(k, scratch.frames[pending[first + k]]);
    EdgeLanes& sectors = scratch.edge_lanes;
    const uint32_t passed =
        edgeAtPixels(edge, triangles, pixel_lanes, samples_, sectors, pass.context.simd);
    for (uint32_t lanes = passed | sectors.deferred; lanes != 0; lanes &= lanes - 1) {
      const int k = __builtin_ctz(lanes);
      const int i = pending[first + k];
      PixelBasis& f = scratch.frames[i];
      std::vector<PixelEdge>& pixel_edges = scratch.edges[i];
      // Written in place: a PixelEdge built on the stack from the lanes' fields and copied in
      // was read back, in 16-byte pieces, before its narrower stores had left the store buffer
      // (a stall on every accepted pair).
      PixelEdge& pixel_edge = pixel_edges.emplace_back();
      int32_t weight = 0;
      if ((passed >> k) & 1u) {
        pixel_edge.edge = sectors.edge[k];
        pixel_edge.runs = sectors.runs[k];
        weight = sectors.weight[k];
      } else if (!edgeAtPixel(edge, triangles, f, samples_, pixel_edge, weight)) {
        pixel_edges.pop_back();
        continue;
      }
      f.reach += std::abs(weight);
      ++work.inside;
    }
  }
}

// Triangles cutting the light and not wholly in front of it: counted sample by sample, less the
// centre segment's crossing, which the stencil counted.
void ExactSoftShadows::collectCuttingTriangles(const LightPass& pass, size_t index,
                                               ExactScratch& scratch) const {
  const EdgeBins& bins = pass.bins;
  const uint32_t* cut_begin = bins.cutting.data() + bins.cutting_begin[index];
  const uint32_t* cut_end = bins.cutting.data() + bins.cutting_begin[index + 1];
  for (uint64_t active = scratch.block.active; active != 0; active &= active - 1)
    scratch.cutting[__builtin_ctzll(active)].clear();
  for (const uint32_t* it = cut_begin; it != cut_end; ++it) {
    const CuttingTriangle& t = pass.edges.cutting[*it];
    uint64_t candidates = edgeCandidates(bins.cutting_tests[*it], scratch.block, pass.context.simd);
    while (candidates != 0) {
      const int i = __builtin_ctzll(candidates);
      candidates &= candidates - 1;
      PixelBasis& f = scratch.frames[i];
      if (t.id == f.primitive) continue;
      setUpIfClear(pass, i, scratch);
      // Outside the cone, or in front of the light, where the edge sums count it.
      if (classifyCutting(t.v[0], t.v[1], t.v[2], f) != CuttingPlace::Across) continue;
      if (!mayBlockSamples(t, f, pass.light)) continue;
      if (segmentHitsTriangle(f.p, pass.light_centre - f.p, 1.0 - kTfarShrink, t))
        --f.centre_count;
      scratch.cutting[i].push_back(&t);
    }
  }
}

// One tile of the pass: its blocks of pixels, each read, tested against the tile's edges and
// cutting triangles, and finished (finishPixel).
void ExactSoftShadows::shadeTile(const LightPass& pass, size_t index, ExactScratch& scratch,
                                 ExactTileWork& work) const {
  const EdgeBinTile bin =
      edgeBinTile(pass.bins, index, pass.eye.depth.width(), pass.eye.depth.height());
  // The thread's scratch outlives the frame: a triangle id it kept from another frame (another
  // camera, another scene) must not pass for this frame's (its eye side differs).
  scratch.origin_triangle = OriginTriangle{};
  // Whether an edge binned here has a triangle cutting the light: only then do the pixels need
  // what the quick reject's test of it reads (PixelBlock::qx ...).
  bool tile_cuts = false;
  for (const uint32_t* it = bin.begin; it != bin.end && !tile_cuts; ++it)
    tile_cuts = pass.bins.tests[*it].any_cuts;
  int x = bin.x0, y = bin.y0;
  while (y < bin.y1) {
    readBlock(pass, bin, x, y, scratch, work);
    PixelBlock& block = scratch.block;
    if (block.active == 0) continue;
    block.has_q = tile_cuts;
    if (tile_cuts) cuttingTestInputs(pass, scratch);
    testEdges(pass, bin, scratch, work);
    collectCuttingTriangles(pass, index, scratch);
    for (uint64_t active = block.active; active != 0; active &= active - 1) {
      const int i = __builtin_ctzll(active);
      vec3 rgb;
      const float grey = finishPixel(scratch.frames[i], scratch.edges[i], scratch.cutting[i],
                                     pass.light, pass.planar, pass.context.simd, scratch, rgb);
      pass.store(scratch.px[i], scratch.py[i], grey, rgb);
    }
  }
}

// Every tile, in parallel, each thread with its scratch; the work counters summed in tile
// order.
void ExactSoftShadows::shadeTiles(const LightPass& pass, Stats& stats) const {
  const size_t tiles = size_t(pass.bins.columns) * size_t(pass.bins.rows);
  std::vector<ExactTileWork> tile_work(tiles);
  ProgressBar progress("exact", tiles, pass.context.show_progress);
  parallelFor(tiles, [&](size_t index) {
    thread_local std::unique_ptr<ExactScratch> scratch_slot;
    if (!scratch_slot || scratch_slot->into.size() != size_t(samples_.n))
      scratch_slot = std::make_unique<ExactScratch>(samples_);
    shadeTile(pass, index, *scratch_slot, tile_work[index]);
    progress.add();
  });
  progress.finish();
  for (const ExactTileWork& w : tile_work) {
    stats.z_reads += w.reads;
    stats.penumbra_tests += w.exact;
    stats.penumbra_inside += w.inside;
  }
}

TechniqueResult ExactSoftShadows::render(const Light& light, const View& view,
                                         const EyeBuffers& eye,
                                         const RenderContext& context) const {
  PENUMBRA_CHECK(isFinite(light.center), "light centre is not finite");
  PENUMBRA_CHECK(std::isfinite(light.radius) && light.radius >= 0.0f,
                 "light radius {} must be a finite number >= 0", light.radius);
  checkLightShape(light);
  const int width = eye.depth.width(), height = eye.depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  Stats culling_stats;
  const CasterCulling culling =
      cullCasters(scene_, light, view, eye, context.caster_culling, culling_stats);
  // A point light: the hard shadow volume, bit for bit.
  if (light.radius == 0.0f) {
    ShadowStencilOptions stencil_options;
    stencil_options.simd = context.simd;
    stencil_options.caster_culling = &culling;
    TechniqueResult hard =
        hardShadowVolumes(scene_, light, view, eye, stencil_options, context.debug_layers);
    putCullingFirst(std::move(culling_stats), hard.stats);
    return hard;
  }
  TechniqueResult result;
  result.stats = std::move(culling_stats);
  Stats& stats = result.stats;
  StencilQuads quads;
  Image<int32_t> stencil;
  std::shared_ptr<const PotentialEdges> edges;
  EdgeBins bins;
  stencilAndEdges(light, view, eye, context, culling, quads, stencil, edges, bins, result);

  Image<float> soft(width, height, 1.0f);
  // Disk and rectangle lights: the fixed points of their area; a textured one's visibility per
  // channel beside the grey one (setChannelVisibility).
  const PlanarSamples planar = planarSamples(light, samples_);
  const bool textured = !planar.texels.empty();
  ChannelVisibility soft_rgb;
  if (textured) {
    for (Image<float>& channel : soft_rgb) channel.resize(width, height, 1.0f);
  }
  // Which visible triangles face away from the light: decided once per triangle, for the
  // samples and the resolve.
  const FacingAway away(scene_, light, view);
  {
    PassTimer timer(stats, "samples");
    const RayOrigins origins(scene_, view);
    const dvec3 light_centre(light.center), eye_position(view.eye);
    const QuadReplay replay{
        quads, eye, light_centre, eye_position,
        -glm::normalize(dvec3(view.view[0][2], view.view[1][2], view.view[2][2])),
        double(view.near_plane),
        std::any_of(quads.zfail.begin(), quads.zfail.end(), [](uint8_t z) { return z != 0; })};
    const LightPass pass{light, view, eye, context, stencil, *edges, bins, quads, away, origins,
                         planar, replay, light_centre, eye_position,
                         dmat4(view.view_projection),
                         2.0 / (double(view.projection[1][1]) * view.height), soft, soft_rgb};
    shadeTiles(pass, stats);
  }
  {
    PassTimer timer(stats, "resolve");
    resolveVisibility(away, eye, result.visibility, [&](int x, int y) { return soft.at(x, y); });
    if (textured) {
      ChannelVisibility channels;
      for (size_t ch = 0; ch < 3; ++ch) {
        resolveVisibility(away, eye, channels[ch],
                          [&](int x, int y) { return soft_rgb[ch].at(x, y); });
      }
      setChannelVisibility(result, light, std::move(channels));
    }
  }
  return result;
}

}  // namespace

TechniqueInfo exactTechnique() {
  TechniqueInfo info;
  info.name = "exact";
  info.counters = casterCullingCounters();
  info.summary = "exact soft shadow volumes: the oracle's answer for a fixed light sample set, "
                 "counted from silhouette edges without rays (Laine et al. 2005)";
  info.traits.soft = true;
  info.traits.exact = true;
  // Against the 1024-ray oracle: the sampling error of 256 fixed samples, like the oracle's own
  // at 256 rays. Measured on the built-in scenes at the conformance size: covered 0.0002-0.0014,
  // penumbra 0.0051-0.0059; twice that is claimed.
  info.traits.covered_mae_bound = 0.003;
  info.traits.penumbra_mae_bound = 0.012;
  OptionTableBuilder<ExactOptions> table;
  samplesOption(table, "light samples per pixel (one fixed stratified set)",
                &ExactOptions::samples, 1, kMaxSamples);
  seedOption(table,
             "the sample set (the oracle's --seed with --sample-set fixed gives the same set)",
             &ExactOptions::seed);
  info.options =
      tileSizeOption(table, "edge binning", &ExactOptions::tile_level, 2, 6)
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
