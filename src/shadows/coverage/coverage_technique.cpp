// Coverage soft shadow volumes (2003; Funk 2004, sections 2.1-2.1.3). For a visible point p:
//   visibility pass 1: V = 1 where the hard shadow volume from the light centre leaves p lit,
//     else 0 (shadow_stencil.h: the same silhouette and quads as `volume`);
//   visibility pass 2: for every silhouette edge e whose region of influence holds p, add
//     sign_e * c_e(p), c_e the fraction of the light that e's hard quad covers seen from p
//     (shape_coverage.h), signed by the side of the quad's plane p is on; clamp V to [0, 1].
// Why it adds up: seen from p, project the silhouette onto the light's plane; with the light
// centre c as origin, Green's theorem splits the covered area into one cone from c per
// silhouette edge. The cone over an edge, cut at the edge, is the triangle (c, a', b') on the
// near side and the projected hard quad on the far side; summed over the closed silhouette the
// cones cover the light once for every time the silhouette winds around c, which is the hard
// shadow at p, and the triangles cover exactly the occluded part. So
//   occluded = |L| [p in the hard shadow] - sum_e (signed area of the quad's part in L),
// and a quad covers nothing of L unless the edge's projection meets L (L is convex and holds
// c), which happens only inside the edge's region: the two planes through the edge tangent to
// the light's bounding sphere and one plane at each end (exact/edge_bins.h, the 2003 wedge as
// a conservative bound; a region need not fit its neighbours', unlike the 2002 wedges whose
// side planes are shared). Each edge's term is continuous and 0 on its region's boundary, so
// tile culling and the quick reject only ever skip zeros.
//
// Pass 1 and pass 2 take their edges from one silhouette (casterVolume, the light centre): the
// quads that jump the hard shadow are exactly the edges whose terms jump back (Funk, section
// 4.2: the thin line along the hard shadow boundary came from two descriptions of the quads).
#include "shadows/coverage/coverage_technique.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "core/parallel.h"
#include "core/pixel_unprojector.h"
#include "core/timer.h"
#include "shadows/coverage/coverage_basis.h"
#include "shadows/coverage/coverage_table.h"
#include "shadows/coverage/disk_coverage_kernel.h"
#include "shadows/coverage/shape_coverage.h"
#include "shadows/coverage/square_coverage_kernel.h"
#include "shadows/coverage/textured_coverage.h"
#include "shadows/shared_options.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/stages/potential_edges/edge_bins.h"
#include "shadows/stages/potential_edges/edge_screen_test.h"
#include "shadows/stages/potential_edges/potential_edges.h"
#include "shadows/stages/silhouettes/facing_away.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {
namespace {

// The region planes' margin, in pixel footprints: only rounding, since the point is the depth
// buffer's own (edge_bins.h). Terms are 0 at the boundary, so a miss there costs nothing.
constexpr double kRegionMarginFootprints = 0.5;

// One facing casts, for open meshes too (silhouette.h, SolidWithHoles): with two-sided casters
// a ray from the light crosses an open surface's front and back sheets, each sheet's edges add
// the light they cover, and a penumbra reads 1 - 2 c, black in its inner half, as the wedges'
// does (their section 8). Pass 1 takes the same policy, so its quads are still the edges'.
constexpr CasterPolicy kCoveragePolicy = CasterPolicy::SolidWithHoles;

struct CoverageEdges {
  PotentialEdges regions;        // end points; no triangles (no per-point silhouette test)
  std::vector<int32_t> weight;   // the silhouette multiplicity, as the quad's stencil weight
};

// Every silhouette edge of every mesh, seen from the light centre exactly as the stencil pass
// sees it (same casterVolume call as shadowStencil).
// `casts`: per mesh, whether it casts (null: every mesh), as ShadowStencilOptions, and
// `culling` the meshes left out as the stencil leaves them out.
CoverageEdges silhouetteEdgesFromCentre(const Scene& scene, const Light& light,
                                        const View& view, const EyeBuffers& eye,
                                        CasterPolicy policy, const std::vector<uint8_t>* casts,
                                        const CasterCulling* culling) {
  CoverageEdges out;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (casts != nullptr && !(*casts)[m]) continue;
    if (culling != nullptr && !culling->mayShadow(m)) continue;
    const CasterVolume volume =
        casterVolume(scene, m, eye, light.center, view, VolumeMode::Auto, policy);
    const Mesh& mesh = scene.meshes[m];
    for (const SilhouetteEdge& e : volume.silhouette.edges) {
      out.regions.edges.push_back(
          PotentialEdge{dvec3(mesh.positions[e.v0]), dvec3(mesh.positions[e.v1]), 0, 0});
      out.weight.push_back(e.multiplicity);
    }
  }
  return out;
}

// One coverage pass's visibility: the area share, or per channel for a textured light (the
// texture-weighted share, which for a uniform texture is the area share).
struct CoverageImages {
  Image<float> grey;      // empty for a textured light
  ChannelVisibility rgb;  // empty for an untextured light
};

struct CoverageTileWork {
  uint64_t reads = 0, tests = 0, pairs = 0, inside = 0;
};

// One block's (pixel, edge) pairs for the kernel, structure of arrays.
struct PairBatch {
  std::vector<float> x0, y0, w0, x1, y1, w1, fraction;
  std::vector<int32_t> weight;
  std::vector<uint8_t> pixel;
  size_t size() const { return pixel.size(); }
  void resize(size_t n) {
    for (auto* v : {&x0, &y0, &w0, &x1, &y1, &w1, &fraction}) v->resize(n);
    weight.resize(n);
    pixel.resize(n);
  }
  void set(size_t k, const dvec3& a, const dvec3& b, int32_t w, int i) {
    x0[k] = float(a.x);
    y0[k] = float(a.y);
    w0[k] = float(a.z);
    x1[k] = float(b.x);
    y1[k] = float(b.y);
    w1[k] = float(b.z);
    weight[k] = w;
    pixel[k] = uint8_t(i);
  }
};

struct CoverageScratch {
  PixelBlock block;
  CoverageBasis bases[kBlockPixels];
  bool with_basis[kBlockPixels];
  int px[kBlockPixels], py[kBlockPixels];
  float sum[kBlockPixels];
  float own_plane[kBlockPixels];
  // The own plane as a half-plane of the light (frontHalfPlane), where it cuts the light.
  dvec2 plane_slope[kBlockPixels];
  double plane_offset[kBlockPixels];
  float hard[kBlockPixels];  // 1 - the stencil's count of volumes holding the point
  // A textured light (textured_coverage.h): per channel, the edges' sum and the own plane's
  // fraction, and whether the basis reads the texture mirrored.
  dvec3 sum_rgb[kBlockPixels];
  dvec3 own_rgb[kBlockPixels];
  bool flip[kBlockPixels];
  PairBatch batch;
  std::vector<uint64_t> candidates;  // per edge of the tile's bin, the pixels it may reach
};

class CoverageShadows final : public PreparedTechnique {
 public:
  CoverageShadows(const CoverageOptions& options, const Scene& scene)
      : options_(options), scene_(scene) {}

  TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                         const RenderContext& context) const override;

 private:
  CoverageOptions options_;
  const Scene& scene_;
  mutable CoverageTableCache tables_;
};

// Unit normal of triangle `id`'s plane, on the side the eye sees (zero for a degenerate one).
dvec3 triangleNormalTowardEye(const Scene& scene, uint32_t id, const View& view) {
  const auto [m, t] = scene.locateTriangle(id);
  const Mesh& mesh = scene.meshes[m];
  const dvec3 a(mesh.vertex(t, 0)), b(mesh.vertex(t, 1)), c(mesh.vertex(t, 2));
  const dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  if (!(length > 0.0)) return dvec3(0.0);
  return (glm::dot(n, dvec3(view.eye) - a) < 0.0 ? -n : n) / length;
}

// What one render's coverage passes share: the frame, the light's coverage table (null:
// analytic) and texture (null: untextured).
struct CoverageFrame {
  const Scene& scene;
  const Light& light;
  const View& view;
  const EyeBuffers& eye;
  const CoverageOptions& options;
  const CoverageTableData* table;
  const TexturedSquare* texture;
  bool simd;
};

// Visibility pass 2 (Funk 2004, section 2.1.3) over the edge bins' tiles, in blocks of
// kBlockPixels pixels: each pixel starts from pass 1's hard value (section 2.1.2, the
// stencil), and every edge whose region holds it adds its signed coverage of the light.
class CoverageTileRender {
 public:
  CoverageTileRender(const CoverageFrame& frame, const Image<int32_t>& stencil,
                     const CoverageEdges& edges, const EdgeBins& bins, CoverageImages& images)
      : f_(frame), eye_(frame.eye), stencil_(stencil), edges_(edges), bins_(bins),
        images_(images), away_(frame.scene, frame.light, frame.view), unproject_(frame.view),
        edge_v_(frame.light.edge_v), textured_(frame.texture != nullptr),
        // The own plane's cut terms: analytic lights only (the table has no half-plane).
        cut_terms_(frame.table == nullptr) {}

  void renderTile(size_t index, CoverageScratch& s, CoverageTileWork& work) const {
    const EdgeBinTile bin =
        edgeBinTile(bins_, index, eye_.depth.width(), eye_.depth.height());
    // No edge reaches the tile (most of a frame's tiles): the hard value is the answer unless
    // a pixel's own plane cuts the light, and only then is the tile set up below.
    if (bin.begin == bin.end && !writeHardTile(bin)) return;
    int x = bin.x0, y = bin.y0;
    while (y < bin.y1) {
      const uint64_t cut = gatherBlock(bin, x, y, s);
      if (s.block.active == 0) continue;
      // The edges' candidate pixels first, then every basis the block needs in one loop
      // (independent iterations: the square roots and divisions of one pixel's basis overlap
      // the next one's), then the pairs.
      const uint64_t reached = findCandidates(bin, s, work);
      const uint64_t with_basis = setUpBases((reached | cut) & s.block.active, s, work);
      cutByOwnPlane(with_basis & cut, s);
      const size_t n = gatherPairs(bin, with_basis, s, work);
      edgeCoverage(s.batch, n);
      sumEdgeTerms(s, n, work);
      writeVisibility(with_basis, s);
    }
  }

 private:
  // Pass 1's answer at a pixel (section 2.1.2): lit where no hard volume holds it.
  void writeHard(int px, int py, int32_t count) const {
    const float hard_visibility = count == 0 ? 1.0f : 0.0f;
    if (textured_) {
      for (Image<float>& c : images_.rgb) c.at(px, py) = hard_visibility;
    } else {
      images_.grey.at(px, py) = hard_visibility;
    }
  }

  // A tile no edge reaches: the hard values written; true when some pixel's own plane cuts
  // the light, so that the tile is still rendered per pixel.
  bool writeHardTile(const EdgeBinTile& bin) const {
    bool any_cut = false;
    for (int py = bin.y0; py < bin.y1; ++py) {
      for (int px = bin.x0; px < bin.x1; ++px) {
        writeHard(px, py, stencil_.at(px, py));
        const uint32_t id = eye_.primitive.at(px, py);
        any_cut |= id != kNoPrimitive && eye_.depth.depth.at(px, py) > 0.0f && !away_(id) &&
                   !away_.clearOfLight(id);
      }
    }
    return any_cut;
  }

  // The next block of the tile's pixels from (x, y), in rows (x and y advanced past it): their
  // hard values written and kept, the points facing the light made active. Returns the pixels
  // whose own plane cuts the light.
  uint64_t gatherBlock(const EdgeBinTile& bin, int& x, int& y, CoverageScratch& s) const {
    PixelBlock& block = s.block;
    block.active = 0;
    uint64_t cut = 0;
    int used = 0;
    for (; y < bin.y1 && used < kBlockPixels;
         x = (x + 1 < bin.x1) ? x + 1 : bin.x0, y += (x == bin.x0)) {
      const int i = used++;
      s.px[i] = x;
      s.py[i] = y;
      block.sx[i] = float(x) + 0.5f;
      block.sy[i] = float(y) + 0.5f;
      block.z[i] = eye_.depth.depth.at(x, y);
      const int32_t count = stencil_.at(x, y);
      writeHard(x, y, count);
      s.hard[i] = 1.0f - float(count);
      const uint32_t id = eye_.primitive.at(x, y);
      if (!(block.z[i] > 0.0f) || id == kNoPrimitive || away_(id)) continue;
      block.active |= uint64_t(1) << i;
      s.with_basis[i] = false;
      s.sum[i] = 0.0f;
      s.own_plane[i] = 1.0f;
      if (textured_) {
        s.sum_rgb[i] = dvec3(0.0);
        s.own_rgb[i] = dvec3(1.0);
      }
      // The visible triangle's plane cuts the light: the part behind it is blocked by the
      // surface itself (the oracle's RayStart::intoSurface; FacingAway when all of it is),
      // so the point needs its basis whether an edge reaches it or not.
      if (!away_.clearOfLight(id)) cut |= uint64_t(1) << i;
    }
    for (; used < kBlockPixels; ++used) block.z[used] = 0.0f;
    return cut;
  }

  // Per edge of the tile's bin, the block's pixels inside its region of influence (section
  // 2.1.3: only those get the edge's term); returns them all.
  uint64_t findCandidates(const EdgeBinTile& bin, CoverageScratch& s,
                          CoverageTileWork& work) const {
    s.candidates.clear();
    uint64_t reached = 0;
    for (const uint32_t* it = bin.begin; it != bin.end; ++it) {
      work.tests += uint64_t(__builtin_popcountll(s.block.active));
      const uint64_t mask = edgeCandidates(bins_.tests[*it], s.block, f_.simd);
      s.candidates.push_back(mask);
      reached |= mask;
    }
    return reached;
  }

  // The light's local basis at each pixel in `todo` (coverage_basis.h); returns those with a basis.
  uint64_t setUpBases(uint64_t todo, CoverageScratch& s, CoverageTileWork& work) const {
    uint64_t with_basis = todo;
    for (; todo != 0; todo &= todo - 1) {
      const int i = __builtin_ctzll(todo);
      s.with_basis[i] = true;
      ++work.reads;
      const dvec3 p = unproject_(s.px[i], s.py[i], s.block.z[i]);
      if (!coverageBasis(f_.light, p, s.bases[i])) {
        with_basis &= ~(uint64_t(1) << i);
        continue;
      }
      s.flip[i] = glm::dot(s.bases[i].b, edge_v_) < 0.0;
    }
    return with_basis;
  }

  // The fraction of the light in front of each pixel's own plane, for the pixels `todo` whose
  // plane cuts it.
  void cutByOwnPlane(uint64_t todo, CoverageScratch& s) const {
    for (; todo != 0; todo &= todo - 1) {
      const int i = __builtin_ctzll(todo);
      const uint32_t id = eye_.primitive.at(s.px[i], s.py[i]);
      const dvec3 normal = triangleNormalTowardEye(f_.scene, id, f_.view);
      if (normal == dvec3(0.0)) continue;
      frontHalfPlane(s.bases[i], normal, s.plane_slope[i], s.plane_offset[i]);
      s.own_plane[i] =
          float(halfPlaneFraction(s.bases[i].outline, s.plane_slope[i], s.plane_offset[i]));
      if (textured_ && s.own_plane[i] < 1.0f) {
        s.own_rgb[i] =
            f_.texture->halfPlaneFraction(s.plane_slope[i], s.plane_offset[i], s.flip[i]);
      }
    }
  }

  // The block's (pixel, edge) pairs, the edge's end points in the pixel's basis, into the
  // batch; returns their number.
  size_t gatherPairs(const EdgeBinTile& bin, uint64_t with_basis, CoverageScratch& s,
                     CoverageTileWork& work) const {
    size_t pairs = 0;
    for (const uint64_t mask : s.candidates) {
      pairs += size_t(__builtin_popcountll(mask & with_basis));
    }
    s.batch.resize(pairs);
    size_t next = 0;
    for (size_t j = 0; j < s.candidates.size(); ++j) {
      const uint32_t edge = bin.begin[j];
      const PotentialEdge& e = edges_.regions.edges[edge];
      for (uint64_t todo = s.candidates[j] & with_basis; todo != 0; todo &= todo - 1) {
        const int i = __builtin_ctzll(todo);
        s.batch.set(next++, s.bases[i].homogeneous(e.a), s.bases[i].homogeneous(e.b),
                    edges_.weight[edge], i);
      }
    }
    work.pairs += pairs;
    return pairs;
  }

  // Each pair's c_e: the fraction of the light the edge's hard quad covers (section 3.1.3,
  // shape_coverage.h), from the table or the kernels.
  void edgeCoverage(PairBatch& b, size_t n) const {
    const DiskCoverageBatch batch{b.x0.data(), b.y0.data(), b.w0.data(),      b.x1.data(),
                                  b.y1.data(), b.w1.data(), b.fraction.data()};
    if (n == 0 || textured_) {
      // no pair: the hard value (and the own plane) stand; a textured light's terms are
      // its own (sumEdgeTerms)
    } else if (f_.table != nullptr) {
      // The table lookups: scalar, in double, the same in both modes.
      for (size_t k = 0; k < n; ++k) {
        b.fraction[k] = f_.table->lookup(dvec3(b.x0[k], b.y0[k], b.w0[k]),
                                         dvec3(b.x1[k], b.y1[k], b.w1[k]), f_.options.table);
      }
    } else if (f_.light.shape == LightShape::Rectangle) {
      squareCoverage(batch, n, f_.simd);
    } else {
      diskCoverage(batch, n, f_.simd);
    }
  }

  // The signed terms sign_e * c_e summed per pixel (section 2.1.3). Where the visible
  // surface's own plane cuts the light (the terminator), the light that is left is the part L'
  // in front of it: the cones over the silhouette cover L' as they cover L (winding number
  // times), so V = f (1 - count) + sum of the edges' terms over L', f = |L'| / |L|, exactly;
  // the terms over L with min(V, f) would count light an occluder hides in front of the plane.
  // Scalar, in double, the same in both modes (analytic lights only: the table has no
  // half-plane). In pair order: the sums do not depend on threads or SIMD.
  void sumEdgeTerms(CoverageScratch& s, size_t n, CoverageTileWork& work) const {
    const PairBatch& b = s.batch;
    for (size_t k = 0; k < n; ++k) {
      const int i = b.pixel[k];
      if (textured_) {
        // Per channel, exact (textured_coverage.h), from the same float end points and cut
        // by the own plane as below.
        dvec2 lo, hi;
        if (clipToOutline(LightOutline::Square, dvec3(b.x0[k], b.y0[k], b.w0[k]),
                          dvec3(b.x1[k], b.y1[k], b.w1[k]), lo, hi)) {
          const dvec3 fraction = f_.texture->beyondFraction(
              lo, hi, s.flip[i], s.own_plane[i] < 1.0f, s.plane_slope[i], s.plane_offset[i]);
          if (fraction != dvec3(0.0)) ++work.inside;
          s.sum_rgb[i] += double(b.weight[k]) * fraction;
        }
        continue;
      }
      float fraction = b.fraction[k];
      if (cut_terms_ && s.own_plane[i] < 1.0f) {
        dvec2 lo, hi;
        fraction = clipToOutline(s.bases[i].outline, dvec3(b.x0[k], b.y0[k], b.w0[k]),
                                 dvec3(b.x1[k], b.y1[k], b.w1[k]), lo, hi)
                       ? float(insideFractionInHalfPlane(s.bases[i].outline, lo, hi,
                                                         s.plane_slope[i], s.plane_offset[i]))
                       : 0.0f;
      }
      if (fraction != 0.0f) ++work.inside;
      s.sum[i] += float(b.weight[k]) * fraction;
    }
  }

  // V = hard + the terms, clamped to [0, 1] (section 2.1.3), or to the own plane's share.
  void writeVisibility(uint64_t with_basis, const CoverageScratch& s) const {
    for (uint64_t active = with_basis; active != 0; active &= active - 1) {
      const int i = __builtin_ctzll(active);
      if (!s.with_basis[i]) continue;
      const float f = s.own_plane[i];
      if (textured_) {
        for (int c = 0; c < 3; ++c) {
          const float fc = float(s.own_rgb[i][c]), sum = float(s.sum_rgb[i][c]);
          images_.rgb[size_t(c)].at(s.px[i], s.py[i]) =
              f < 1.0f ? std::clamp(fc * s.hard[i] + sum, 0.0f, fc)
                       : std::clamp(s.hard[i] + sum, 0.0f, 1.0f);
        }
        continue;
      }
      images_.grey.at(s.px[i], s.py[i]) =
          cut_terms_ && f < 1.0f ? std::clamp(f * s.hard[i] + s.sum[i], 0.0f, f)
                                 : std::min(std::clamp(s.hard[i] + s.sum[i], 0.0f, 1.0f), f);
    }
  }

  const CoverageFrame& f_;
  const EyeBuffers& eye_;
  const Image<int32_t>& stencil_;
  const CoverageEdges& edges_;
  const EdgeBins& bins_;
  CoverageImages& images_;
  const FacingAway away_;
  const PixelUnprojector unproject_;
  const dvec3 edge_v_;
  const bool textured_, cut_terms_;
};

// One coverage pass (Funk 2004, section 2.1): pass 1's stencil, the silhouette edges from the
// light centre, their regions binned to tiles, and pass 2 over the tiles. `policy` for the
// casters, `casts` for which meshes.
CoverageImages coveragePass(const CoverageFrame& f, ShadowStencilOptions& stencil_options,
                            CasterPolicy policy, const std::vector<uint8_t>* casts,
                            Stats& stats) {
  const int width = f.eye.depth.width(), height = f.eye.depth.height();
  stencil_options.policy = policy;
  stencil_options.casting_meshes = casts;
  const Image<int32_t> stencil =
      shadowStencil(f.scene, f.light.center, f.view, f.eye, stencil_options, stats);
  CoverageEdges edges;
  {
    PassTimer timer(stats, "edges");
    edges = silhouetteEdgesFromCentre(f.scene, f.light, f.view, f.eye, policy, casts,
                                      stencil_options.caster_culling);
    stats.wedges += edges.weight.size();
  }
  EdgeBins bins;
  {
    PassTimer timer(stats, "binning");
    // The regions of the light's bounding sphere (light.h: radius bounds every shape).
    Light bound = f.light;
    bound.shape = LightShape::Sphere;
    bins = binEdges(edges.regions, bound, f.view, f.eye.depth, f.options.tile_level,
                    kRegionMarginFootprints);
    stats.tiles_tested += bins.tiles_tested;
    stats.tiles_culled += bins.tiles_culled;
  }
  CoverageImages images;
  if (f.texture != nullptr) {
    for (Image<float>& c : images.rgb) c.resize(width, height, 1.0f);
  } else {
    images.grey.resize(width, height, 1.0f);
  }
  PassTimer timer(stats, "coverage");
  const CoverageTileRender render(f, stencil, edges, bins, images);
  const size_t tiles = size_t(bins.columns) * size_t(bins.rows);
  std::vector<CoverageTileWork> tile_work(tiles);
  parallelFor(tiles, [&](size_t index) {
    thread_local std::unique_ptr<CoverageScratch> scratch_slot;
    if (!scratch_slot) scratch_slot = std::make_unique<CoverageScratch>();
    render.renderTile(index, *scratch_slot, tile_work[index]);
  });
  for (const CoverageTileWork& w : tile_work) {
    stats.z_reads += w.reads;
    stats.penumbra_tests += w.pairs;
    stats.penumbra_inside += w.inside;
  }
  return images;
}

TechniqueResult CoverageShadows::render(const Light& light, const View& view,
                                        const EyeBuffers& eye,
                                        const RenderContext& context) const {
  checkLightShape(light);
  const int width = eye.depth.width(), height = eye.depth.height();
  PENUMBRA_CHECK(width == view.width && height == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", width, height, view.width,
                 view.height);
  ShadowStencilOptions stencil_options;
  stencil_options.simd = context.simd;
  Stats culling_stats;
  const CasterCulling culling =
      cullCasters(scene_, light, view, eye, context.caster_culling, culling_stats);
  stencil_options.caster_culling = &culling;
  // A point light: pass 1 alone, the hard shadow volume bit for bit.
  if (!(light.radius > 0.0f)) {
    TechniqueResult hard =
        hardShadowVolumes(scene_, light, view, eye, stencil_options, context.debug_layers);
    putCullingFirst(std::move(culling_stats), hard.stats);
    return hard;
  }
  // A textured rectangle (light.h): the exact per-channel path beside the area path.
  const bool textured = light.texture != nullptr;
  PENUMBRA_CHECK(!textured || options_.table == CoverageTable::Analytic,
                 "coverage: the coverage table holds an untextured light's areas; a textured "
                 "light takes --coverage-table analytic");
  std::unique_ptr<TexturedSquare> texture;
  if (textured) texture = std::make_unique<TexturedSquare>(*light.texture);
  const CoverageTableData* table = nullptr;
  TechniqueResult result;
  result.stats = std::move(culling_stats);
  Stats& stats = result.stats;
  // Pass 1's stencil stage draws the silhouettes from the centre (the edges pass 2 takes) and
  // its culled tiles.
  if (context.debug_layers) stencil_options.debug_layers = &result.debug_layers;
  if (options_.table != CoverageTable::Analytic) {
    PassTimer timer(stats, "table");
    table = &tables_.get(light, options_.table_size);
  }
  const CoverageFrame frame{scene_, light,         view,         eye,
                            options_, table,       texture.get(), context.simd};
  CoverageImages soft = coveragePass(frame, stencil_options, kCoveragePolicy, nullptr, stats);
  // Open meshes cast one facing, and a ray through a hole (a terrain's border under a low
  // light) misses it: the other facing of those meshes, in a pass of its own, counts those
  // rays, and the darker visibility is kept, as the wedges do (wedge_technique.cpp).
  const std::vector<uint8_t> other_facing = options_.other_facing_pass
                                                ? openMeshesWithBothFacings(scene_, light.center)
                                                : std::vector<uint8_t>();
  if (!other_facing.empty()) {
    const CoverageImages other = coveragePass(
        frame, stencil_options, CasterPolicy::SolidWithHolesOtherFacing, &other_facing, stats);
    // Per channel for a textured light (the grey image is then empty, and the rgb ones are
    // otherwise): each image keeps the darker of the two passes.
    const auto darker = [](Image<float>& mine, const Image<float>& theirs) {
      for (size_t i = 0; i < mine.size(); ++i) mine[i] = std::min(mine[i], theirs[i]);
    };
    darker(soft.grey, other.grey);
    for (int c = 0; c < 3; ++c) darker(soft.rgb[size_t(c)], other.rgb[size_t(c)]);
  }
  {
    PassTimer timer(stats, "resolve");
    if (textured) {
      ChannelVisibility channels;
      for (int c = 0; c < 3; ++c) {
        resolveVisibility(scene_, light, view, eye, channels[size_t(c)],
                          [&](int x, int y) { return soft.rgb[size_t(c)].at(x, y); });
      }
      setChannelVisibility(result, light, std::move(channels));
    } else {
      resolveVisibility(scene_, light, view, eye, result.visibility,
                        [&](int x, int y) { return soft.grey.at(x, y); });
    }
  }
  return result;
}

}  // namespace

std::string coverageTableName(CoverageTable table) {
  switch (table) {
    case CoverageTable::Analytic:
      return "analytic";
    case CoverageTable::Nearest:
      return "nearest";
    case CoverageTable::Quadlinear:
      return "quadlinear";
  }
  return "unknown";
}

TechniqueInfo coverageTechnique() {
  TechniqueInfo info;
  info.name = "coverage";
  info.counters = casterCullingCounters();
  info.aliases = {"ssv-2003"};
  info.summary = "coverage soft shadow volumes (2003 / Funk 2004): hard volume from the centre, "
                 "plus each silhouette edge's exact covered fraction of a sphere, disk or "
                 "rectangle light";
  info.traits.soft = true;
  // Against the 1024-ray oracle at the conformance size: covered 0.0001-0.0079, penumbra
  // 0.0028-0.0529, the worst on year2002 whose occluders' penumbrae overlap (the edges' terms
  // add up, too dark there, as the wedges' do: 2002 paper, section 8). Bounds: about 1.5x.
  info.traits.covered_mae_bound = 0.012;
  info.traits.penumbra_mae_bound = 0.08;
  OptionTableBuilder<CoverageOptions> table;
  table.choice("coverage-table",
                  "per-edge coverage: exact area (analytic), or the paper's 4D coverage table "
                  "with nearest or quadlinear lookup",
                  &CoverageOptions::table,
                  {{"analytic", CoverageTable::Analytic},
                   {"nearest", CoverageTable::Nearest},
                   {"quadlinear", CoverageTable::Quadlinear}})
          .integer("coverage-table-size",
                   "entries per table parameter (n^4 entries; the paper's 32: 1024 x 1024)",
                   &CoverageOptions::table_size, kMinCoverageTableSize, kMaxCoverageTableSize);
  info.options =
      tileSizeOption(table, "edge binning", &CoverageOptions::tile_level, 2, 6)
          .flag("one-facing",
                "open meshes cast one facing only (faster where an open mesh faces the light "
                "both ways, but light passes through its holes)",
                &CoverageOptions::other_facing_pass, false)
          .check([](const CoverageOptions& o) {
            PENUMBRA_CHECK(o.tile_level >= 2 && o.tile_level <= 6,
                           "coverage: tile level {} is outside 2..6 (4 to 64 pixels)",
                           o.tile_level);
          })
          .describe([](const CoverageOptions& o) {
            return (o.table == CoverageTable::Analytic
                        ? fmt::format("analytic, {}x{} tiles", 1 << o.tile_level,
                                      1 << o.tile_level)
                        : fmt::format("{} table {}^4, {}x{} tiles", coverageTableName(o.table),
                                      o.table_size, 1 << o.tile_level, 1 << o.tile_level)) +
                   (o.other_facing_pass ? "" : ", one facing");
          })
          .build();
  info.prepare = [](const std::any& options, const Scene& scene) {
    return std::make_unique<CoverageShadows>(std::any_cast<const CoverageOptions&>(options),
                                             scene);
  };
  return info;
}

}  // namespace penumbra
