#pragma once
// One pixel of the exact soft shadow volumes: its shaded point and light basis, and the exact
// test of one potential silhouette edge there (exact_technique.cpp says how they add up).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "shadows/exact/light_samples.h"
#include "shadows/exact/sample_kernel.h"
#include "shadows/stages/light_sampling/light_sampling.h"
#include "shadows/stages/light_sampling/ray_origin.h"
#include "shadows/stages/potential_edges/potential_edges.h"
#include "shadows/stages/stencil/shadow_stencil.h"

namespace penumbra {

// A visible point and the light as it sees it: the oracle's ray origin and sample cone.
struct PixelBasis {
  // Set up only once an edge may matter (setupPixel); until then all that is known is the
  // stencil, and the pixel's triangle has the whole light in front of it
  // (FacingAway::clearOfLight).
  bool ready = false;
  // A disk or rectangle light (light.h): its samples are fixed points of its area, and every
  // test below bounds it by its bounding ball (light.radius), which holds them all.
  bool planar = false;
  // A point inside a planar light's bounding ball (setupPixel): no cone holds the light, so
  // its samples are counted segment by segment instead (exact_technique.cpp).
  bool inside_light = false;
  int32_t stencil = 0;
  uint32_t primitive = kNoPrimitive;  // the visible triangle, left out of every count
  RayStart start;
  dvec3 p{0.0};  // the float origin the oracle's rays start from, widened
  SphereCone cone;
  dvec3 axis{0.0}, tangent{0.0}, bitangent{0.0};
  double light_radius = 0;  // of the light's disk on the plane at unit distance
  double z_min = 0;         // edges are clipped to this depth along the axis
  double light_near = 0;    // |c - p| - r: the light's nearest depth along the axis
  double sin_max = 0, cos_max = 1;  // of the cone's half-angle
  int32_t centre_count = 0;  // D at the centre, the visible triangle left out
  // How near the two points a quad's plane must pass to be replayed (quadCountShift): a few
  // times their distance, and the float rounding of the depth-buffer point.
  double quad_reach = 0;
  int64_t reach = 0;        // how far the edges can move any sample's count from the centre's
};

// An edge that changes samples of a pixel, and the blocks of samples its sector may hold.
struct PixelEdge {
  SampleEdge edge;
  SampleRuns runs;
};

// The oracle shortens its shadow rays by this much so the light point itself never blocks
// (reference_technique.cpp).
inline constexpr double kTfarShrink = 1e-6;

// Where a triangle whose plane cuts the light stands, seen from a pixel's point: the part of it
// inside the point's cone toward the light (clipped to a square pyramid around the cone) is
// empty (Outside: no segment toward the light crosses it), lies wholly nearer along the axis
// than the light's nearest depth (InFront: every segment that crosses it does so before the
// light; depth along the axis grows along each), or neither (Across: some segments may cross
// it beyond the light). The edge sums take InFront triangles as any other and leave the rest;
// Across ones are counted sample by sample. Both use this one test.
enum class CuttingPlace { Outside, InFront, Across };
CuttingPlace classifyCutting(const dvec3& a, const dvec3& b, const dvec3& c, const PixelBasis& f);

// False when the triangle cannot block any sample of the point: the point lies outside the
// triangle's region, the triangle lies wholly behind the light centre, or the whole cap of the
// light the point sees lies on the point's side of the triangle's plane (a segment from the
// point to the cap then never crosses the plane).
bool mayBlockSamples(const CuttingTriangle& t, const PixelBasis& f, const Light& light);

// The blocks of samples whose angle around the light centre the triangle's projection from the
// point can reach (all of them when it surrounds the centre or reaches behind the point).
SampleRuns triangleRuns(const CuttingTriangle& t, const PixelBasis& f,
                        const SortedSamples& samples);

// Does o + t d, 0 < t < t_max, cross the triangle abc (Moller and Trumbore 1997, in double)?
bool segmentHitsTriangle(const dvec3& o, const dvec3& d, double t_max, const dvec3& a,
                         const dvec3& b, const dvec3& c);
inline bool segmentHitsTriangle(const dvec3& o, const dvec3& d, double t_max,
                                const CuttingTriangle& t) {
  return segmentHitsTriangle(o, d, t_max, t.v[0], t.v[1], t.v[2]);
}

// Sets up the basis of a pixel; false when its visibility is already known (`known`), or, for a
// planar light, when the point lies inside its bounding ball (f.inside_light).
// `triangle`: the work item's last visible triangle, for RayOrigins::start.
// `replayed`: the visible triangle's mesh is a z-pass volume whose quads quadCountShift moves to
// the shaded point, and the visible triangle is taken out as the segment from there to the
// light centre crosses it; else as the stencil counted it at the depth-buffer point.
bool setupPixel(int x, int y, float depth, uint32_t primitive, int32_t stencil,
                const RayOrigins& origins, const Light& light, OriginTriangle& triangle,
                bool replayed, PixelBasis& f, float& known);

// For a z-fail volume's edge (quadCountShift replays z-pass quads only): how the count at the
// light centre changes from the pixel's depth-buffer point, where the stencil counted it, to
// the shaded point f.p the oracle's rays leave from, in double: by the edge's
// triangles that the segment toward the centre starts or stops crossing when it sweeps over
// the edge, which happens where the path between the two points crosses the edge's shadow
// quad from the centre. For an edge of the visible triangle (the stencil skips its quad at the
// triangle's pixels, ShadowStencilOptions::skip_own_quads, and the origin was snapped onto the
// triangle, often right at that edge) the neighbours are tested directly from both points.
int32_t centreCountShift(const PotentialEdge& e, const EdgeTriangle* triangles,
                         const PixelBasis& f, const dvec3& centre, const dvec3& eye);

// The stencil's count moved from pixel (x, y)'s depth-buffer point to the shaded point f.p over
// the quad of edge e, for a z-pass volume: the stencil's own decision for each piece of the quad
// at the pixel, replayed (rasterizer.h: stencilContributionAt), against whether the segment from
// the eye to f.p crosses the quad, in double. Beside the visible triangle's own count, this is
// all that separates the stencil from the count at f.p: a quad's decision can differ between
// the two points only where it passes between or through them, inside the edge's region.
// `zfail` is set for a z-fail volume's quad, which this leaves to centreCountShift (its caps
// would need the same).
struct QuadReplay {
  const StencilQuads& quads;
  const EyeBuffers& eye;
  dvec3 centre, eye_position;
  dvec3 forward;      // the view direction (unit), for the near plane
  double near_plane;  // crossings nearer the eye than this are clipped away by the stencil
  bool any_zfail;     // some mesh's volume was drawn z-fail
};
int32_t quadCountShift(const PotentialEdge& e, const QuadReplay& replay, int x, int y,
                       const PixelBasis& f, bool& zfail);

// The rest of what separates the stencil from the count at f.p on a z-pass volume: the caps.
// The depth-buffer point is seen from the eye, but the origin, snapped onto the visible
// triangle and lifted off it, can lie just behind a neighbouring triangle (at a concave fold);
// the segment from the eye then crosses that triangle, which enters (from the light centre's
// side, +1) or leaves (-1) its volume: the count a z-pass stencil would have there.
// `neighbours`: the triangles sharing a vertex with the visible one (VertexRings).
int32_t capCrossings(const Scene& scene, const std::vector<uint32_t>& neighbours,
                     const PixelBasis& f, const dvec3& centre, const dvec3& eye_position);

// The exact test of one edge at one point: false when the edge changes none of its samples,
// else `out` says which samples it changes and by how much.
bool edgeAtPixel(const PotentialEdge& e, const EdgeTriangle* triangles, const PixelBasis& f,
                 const SortedSamples& samples, PixelEdge& pixel_edge, int32_t& weight_out);

// The same test of one edge at up to kEdgeLanes points at once (SIMD over the points in double,
// the same operations in the same order; edgeAtPixelsScalar is its scalar twin). The points are
// the bases' fields edgeAtPixel reads, one lane each (setLane). Returns bit k set for each
// lane k whose test passes, with its SampleEdge, weight, the pseudo-angle range [from, to] of
// its sector and its sample runs (sampleRuns of that range) in `out`. A triangle of the edge
// whose plane cuts the light counts where classifyCutting finds it in front of the light; its
// quick test (the whole triangle nearer than the light) is made here, and the lanes where that
// fails are left to edgeAtPixel (bit k of out.deferred), which clips it to the point's cone.
inline constexpr int kEdgeLanes = 8;
struct PixelLanes {
  alignas(64) double px[kEdgeLanes], py[kEdgeLanes], pz[kEdgeLanes];
  alignas(64) double ax[kEdgeLanes], ay[kEdgeLanes], az[kEdgeLanes];  // axis
  alignas(64) double tx[kEdgeLanes], ty[kEdgeLanes], tz[kEdgeLanes];  // tangent
  alignas(64) double bx[kEdgeLanes], by[kEdgeLanes], bz[kEdgeLanes];  // bitangent
  alignas(64) double z_min[kEdgeLanes], light_radius[kEdgeLanes], light_near[kEdgeLanes];
  alignas(64) double primitive[kEdgeLanes];  // the visible triangle's id (exact in double)
  int count = 0;
  void setLane(int k, const PixelBasis& f);
};
struct EdgeLanes {
  SampleEdge edge[kEdgeLanes];
  int32_t weight[kEdgeLanes];
  double from[kEdgeLanes] = {}, to[kEdgeLanes] = {};
  SampleRuns runs[kEdgeLanes];
  uint32_t deferred = 0;
};
uint32_t edgeAtPixels(const PotentialEdge& e, const EdgeTriangle* triangles,
                      const PixelLanes& pixels, const SortedSamples& samples, EdgeLanes& out,
                      bool simd);
uint32_t edgeAtPixelsScalar(const PotentialEdge& e, const EdgeTriangle* triangles,
                            const PixelLanes& pixels, const SortedSamples& samples,
                            EdgeLanes& out);

}  // namespace penumbra
