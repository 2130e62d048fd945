#pragma once
// The edges that can change what a point sees of a spherical light, and where on screen they
// can do it (Laine et al. 2005, "potential silhouette edges"; docs/exact-soft-shadows.md).
//
// An edge matters to a point p only if it is a silhouette seen from p (its triangles lie on one
// side of the plane through p and the edge) and its projection from p overlaps the light. Then
// p, a point of the edge and a point q of the light are collinear, the plane through q and the
// edge is the plane through p and the edge, and the edge is a silhouette seen from q too. As q
// moves through the light ball the edge's status changes only where q crosses the plane of one
// of its triangles. So an edge of two triangles is a potential silhouette exactly when it is a
// silhouette from the light centre or the plane of one of its triangles cuts the ball; edges of
// one triangle, or of three or more, always are.
//
// Numeric conventions: world space in double (the meshes are float, widened once). Plane values
// are signed distances (unit normals).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/light.h"
#include "scene/scene.h"

namespace penumbra {

// A triangle using an edge a -> b (PotentialEdge).
//
// Seen from a point p, the triangle lies on one side of the plane through p and the edge:
//   side = sign(dot(cross(a - p, b - p), opposite - p)) = -winding * sign(plane value at p),
// since that triple product is minus the volume of (a, b, opposite, p). So the silhouette test
// at a point is one plane evaluation per triangle, the same value that says whether the
// triangle lies between the point and the light (docs/exact-soft-shadows.md).
//
// A triangle whose plane cuts the light ball (`cuts`) may be crossed before the light by some
// segments toward it and after it by others: the edge sums take it only where its part inside
// the point's cone toward the light lies wholly in front of the light (pixel_edges.h,
// classifyCutting); elsewhere it is a CuttingTriangle, counted sample by sample.
struct EdgeTriangle {
  uint32_t id;        // global triangle id (EyeBuffers::primitive)
  bool light_above;   // the light centre lies strictly on the positive side of its plane
  bool cuts;          // its plane cuts the light ball
  int8_t winding;     // +1: the triangle's normal is that of (a, b, opposite); -1: reversed
  dvec3 opposite;     // its vertex off the edge
  dvec3 normal;       // its plane: dot(normal, x) + offset, unit normal
  double offset;
};

struct PotentialEdge {
  dvec3 a, b;
  uint32_t first_triangle, triangle_count;  // into PotentialEdges::triangles
  // Its number among the scene's edges (shadow_stencil.h: sceneEdgeOffsets), or none.
  uint32_t scene_edge = 0xffffffffu;
  // (a - c) x (b - c), c the light centre: the normal of the plane of the edge's shadow quad
  // from the centre (pixel_edges.h: quadCountShift), set once per light.
  dvec3 centre_normal{0.0};
};

// A triangle whose plane cuts the light ball (a wall through the light, a floor the light sinks
// into, the rim of a curved occluder seen edge-on from the light): it can block rays toward the
// part of the light beyond its plane whichever side of it the centre is on. Where it is not
// wholly in front of the light (pixel_edges.h, classifyCutting) it is tested against each
// sample's segment.
struct CuttingTriangle {
  uint32_t id;
  dvec3 v[3];
  dvec4 plane;  // unit normal and offset
  // The points some segment from the light through it reaches lie inside these planes
  // (value >= 0; circumscribedPyramid); none when the triangle comes near the light.
  std::array<dvec4, 4> region;
  int region_count = 0;
};

// The region of anything inside the ball of radius rho around m, for a light ball (c, r): every
// segment from the light through it passes through that ball, so the region lies in the cone of
// the two balls' internal tangents, apex where they cross, O = c + (m - c) r / (r + rho),
// half-angle asin((r + rho) / |m - c|). Writes the four planes through O that circumscribe it
// (unit normal n and offset, inside where n . x + offset >= 0) and returns 4, or returns 0
// when the ball comes near the light (the half-angle would pass asin 0.9).
int circumscribedPyramid(const dvec3& c, double r, const dvec3& m, double rho, dvec4 planes[4]);

struct PotentialEdges {
  std::vector<PotentialEdge> edges;
  std::vector<EdgeTriangle> triangles;
  std::vector<CuttingTriangle> cutting;
  size_t scene_edges = 0;  // edges of the scene's meshes, for the ratio
  size_t skipped_edges = 0;  // of those, in clusters skipped whole (EdgeGeometry)
};

// Bounds over the planes of a cluster of triangles, so that one test can tell that the light
// centre lies on the same side of every plane, farther from each than the "cuts the ball" test
// reaches (Laine et al. 2005, section 4: the potential silhouette edges found "hierarchically";
// here a flat list of clusters). Every unit normal lies within `half_angle` of `axis`, and
// every plane passes within `plane_reach` of `centre`; the triangles' vertices lie within
// `vertex_reach` of it. Not `usable` when a triangle has no area, the normals spread over a
// hemisphere or more, or (edge clusters) an edge is not one of two triangles wound opposite ways.
struct PlaneCluster {
  dvec3 axis{0.0};
  double cos_half = -1.0, sin_half = 0.0;
  dvec3 centre{0.0};
  double plane_reach = 0.0, vertex_reach = 0.0;
  bool usable = false;
};

// +1 when every plane of the cluster has the light centre c on its positive side and the ball
// (c, r) does not reach it (with the slack potentialEdges gives that test, and a margin far
// above the rounding of either test), -1 when every plane has it on its negative side so, 0 when
// the bounds cannot tell.
int clusterSide(const PlaneCluster& cluster, const dvec3& c, double r);

// Clusters: consecutive edges (EdgeAdjacency's order: sorted by the smaller vertex index, so
// neighbours on a scanned mesh) or consecutive triangles.
inline constexpr size_t kEdgesPerCluster = 16;
inline constexpr size_t kTrianglesPerCluster = 16;

// What potentialEdges needs of the scene whatever the light, built once per scene: every
// triangle's plane (unit normal and offset; all 0 for a triangle of zero area), per edge use
// (EdgeAdjacency::uses) the triangle's winding along the edge (EdgeTriangle), and the clusters'
// bounds. A cluster of edges whose triangles the light sees all from the front, or all from
// the back, holds no potential silhouette edge (two triangles wound opposite ways with the
// centre on the same side of both, neither plane cutting the ball): potentialEdges skips its
// edges without visiting them; a cluster of triangles so, the per-triangle plane tests.
// Empty cluster lists: every edge and triangle is visited (the same result, tests compare).
struct EdgeGeometry {
  std::vector<std::vector<dvec4>> planes;    // per mesh, per triangle
  std::vector<std::vector<int8_t>> winding;  // per mesh, per edge use
  std::vector<std::vector<PlaneCluster>> edge_clusters;      // per mesh, kEdgesPerCluster each
  std::vector<std::vector<PlaneCluster>> triangle_clusters;  // per mesh, kTrianglesPerCluster
};
EdgeGeometry edgeGeometry(const Scene& scene);

// Every potential silhouette edge of the scene for `light` (radius > 0), in mesh and edge order,
// and every triangle cutting the light. Zero-area triangles never block a ray and are left out.
PotentialEdges potentialEdges(const Scene& scene, const EdgeGeometry& geometry,
                              const Light& light);
inline PotentialEdges potentialEdges(const Scene& scene, const Light& light) {
  return potentialEdges(scene, edgeGeometry(scene), light);
}

}  // namespace penumbra
