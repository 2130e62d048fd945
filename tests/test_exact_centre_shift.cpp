// The exact soft shadow volumes take the count at the light centre from the stencil, which was
// decided at the pixel's depth-buffer point, while the oracle's rays leave from that point
// snapped onto the visible triangle. For a z-fail volume centreCountShift says how the count
// changes between the two: by the edge's triangles the segment toward the centre starts or
// stops crossing where the path between the points crosses the edge's shadow quad. For a
// z-pass volume the stencil's quads are replayed (test_shadow_stencil_replay.cpp) and the caps
// the origin may lie behind are counted by capCrossings (below).
#include <gtest/gtest.h>

#include "scene/scene_builder.h"
#include "shadows/exact/pixel_edges.h"
#include "shadows/exact/vertex_rings.h"

namespace penumbra {
namespace test_exact_centre_shift {

// The light centre above the origin; an open edge along z at height 2, x = 0, its one
// triangle reaching toward -x (so it shadows the floor at x < 0 below it, seen from the centre).
// The edge's quad is the part beyond the edge of the plane x = 0: x = 0, y < 2.
struct HalfPlane {
  dvec3 centre{0.0, 10.0, 0.0};
  dvec3 eye{5.0, 3.0, 5.0};
  // (a - c) x (b - c) = (-16, 0, 0): the quad's plane x = 0 (potentialEdges sets it).
  PotentialEdge edge{dvec3(0.0, 2.0, -1.0), dvec3(0.0, 2.0, 1.0), 0, 1, 0, dvec3(-16, 0, 0)};
  std::vector<EdgeTriangle> triangles{
      EdgeTriangle{7, true, false, 1, dvec3(-1.0, 2.0, 0.0), dvec3(0.0, 1.0, 0.0), -2.0}};

  PixelBasis frame(const dvec3& depth_point, const dvec3& shaded, uint32_t visible) const {
    PixelBasis f;
    f.start.depth_point = depth_point;
    f.p = shaded;
    f.primitive = visible;
    return f;
  }
  int32_t shift(const dvec3& depth_point, const dvec3& shaded, uint32_t visible = 99) const {
    return centreCountShift(edge, triangles.data(), frame(depth_point, shaded, visible), centre,
                            eye);
  }
};

// From a floor point just right of x = 0 (lit at the centre) to one just left (the triangle
// between it and the centre): +1, and back -1. If these failed, a pixel whose depth-buffer
// point and shaded point straddle another object's hard shadow boundary would keep the
// stencil's count and be lit where the oracle's rays are all blocked, or the reverse.
TEST(ExactCentreShift, CrossingTheQuadCountsTheTriangleEnteredOrLeft) {
  const HalfPlane s;
  EXPECT_EQ(s.shift(dvec3(1e-3, 0.0, 0.0), dvec3(-1e-3, 0.0, 0.0)), 1);
  EXPECT_EQ(s.shift(dvec3(-1e-3, 0.0, 0.0), dvec3(1e-3, 0.0, 0.0)), -1);
}

// Both points on one side, or crossing the plane x = 0 outside the quad (above the edge, or
// beyond its ends): no change. If these failed, pixels near the plane of an edge but nowhere
// near its shadow would gain or lose a whole light.
TEST(ExactCentreShift, NoCrossingOfTheQuadNoShift) {
  const HalfPlane s;
  EXPECT_EQ(s.shift(dvec3(2e-3, 0.0, 0.0), dvec3(1e-3, 0.0, 0.0)), 0);
  EXPECT_EQ(s.shift(dvec3(1e-3, 5.0, 0.0), dvec3(-1e-3, 5.0, 0.0)), 0);   // between edge and centre
  EXPECT_EQ(s.shift(dvec3(1e-3, 0.0, 4.0), dvec3(-1e-3, 0.0, 4.0)), 0);   // past the edge's end
}

// A depth-buffer point within rounding of the quad's plane along the eye's ray: the stencil's
// side was rounding, and the count is left as it is. If this failed, a surface whose plane
// holds the light centre would flip between lit and dark along its edges.
TEST(ExactCentreShift, RoundingTiesAreLeftAlone) {
  const HalfPlane s;
  EXPECT_EQ(s.shift(dvec3(1e-9, 0.0, 0.0), dvec3(-1e-3, 0.0, 0.0)), 0);
}

// An edge of the visible triangle (a floor, x < 0) and a neighbour across it. The oracle's
// origin sits on the floor by the edge; the depth-buffer point, which the rasterizer's snapping
// put just past the edge, lies beyond the neighbour's plane or on the neighbour itself.
const EdgeTriangle kFloor{7, true, false, 1, dvec3(-1, 0, 0), dvec3(0, 1, 0), 0.0};
// The shift across the floor's edge x = 0 with `neighbour` beyond it, for a depth-buffer point
// just past the edge and the origin `origin` on the floor.
int32_t floorEdgeShift(const EdgeTriangle& neighbour, const dvec3& origin, const dvec3& centre) {
  const std::vector<EdgeTriangle> triangles{kFloor, neighbour};
  PixelBasis f;
  f.primitive = kFloor.id;
  f.start.depth_point = dvec3(1e-4, 0, 0);
  f.p = origin;
  return centreCountShift(PotentialEdge{dvec3(0, 0, -1), dvec3(0, 0, 1), 0, 2}, triangles.data(),
                          f, centre, dvec3(-4, 5, 3));
}

// A wall rising at x = 0 with the light behind it: segments from the origin toward the centre
// cross the wall, those from the depth-buffer point behind it do not: +1. If this failed,
// floor pixels along the foot of a wall that hides the light would be lit.
TEST(ExactCentreShift, NeighbourBetweenTheOriginAndTheCentre) {
  const EdgeTriangle wall{8, true, false, 1, dvec3(0, 1, 0), dvec3(1, 0, 0), 0.0};
  EXPECT_EQ(floorEdgeShift(wall, dvec3(-1e-4, 1e-6, 0), dvec3(5, 3, 0)), 1);
}

// The floor continues flat past the edge (a neighbour in its plane) and the light is below
// it: the stencil counted the neighbour under the depth-buffer point as it counts a visible
// triangle with the centre behind it, while the origin's segment passes the neighbour by: -1.
// If this failed, pixels along the seam of a flat or smooth surface at its terminator would
// stay dark where the oracle sees part of the light.
TEST(ExactCentreShift, DepthPointOnTheNeighbourCountedAsTheStencilDid) {
  const EdgeTriangle flat{8, false, false, 1, dvec3(1, 0, 0), dvec3(0, 1, 0), 0.0};
  EXPECT_EQ(floorEdgeShift(flat, dvec3(-1e-4, 1e-5, 0), dvec3(0.5, -3, 0)), -1);
}

// An edge of two triangles on opposite sides of the quad's plane is no silhouette from the
// centre and has no quad: the two changes cancel. If this failed, every interior edge of a mesh
// would move the count of the pixels its plane passes between.
TEST(ExactCentreShift, NoSilhouetteNoShift) {
  HalfPlane s;
  s.edge.triangle_count = 2;
  s.triangles.push_back(
      EdgeTriangle{8, true, false, -1, dvec3(1.0, 2.0, 0.0), dvec3(0.0, 1.0, 0.0), -2.0});
  EXPECT_EQ(s.shift(dvec3(1e-3, 0.0, 0.0), dvec3(-1e-3, 0.0, 0.0)), 0);
}

// A floor (x < 0, y = 0) meeting a wall (x = 0, rising) in one mesh, the light beyond the wall,
// the eye in front of it. The oracle's origin, snapped to the floor's border and lifted off
// it, can end up just past the wall's plane, where the segment from the eye crosses the wall:
// along that segment a z-pass count leaves the wall's volume through the wall itself (-1), as
// the origin, on the light's side of the wall, is not shadowed by it; an origin in front of the
// wall crosses nothing. If this failed, the stencil's count, taken in front of the wall, would
// stand for an origin the wall no longer shadows.
TEST(ExactCentreShift, OriginBehindANeighbourCrossesItsCap) {
  Scene scene;
  const uint32_t material = addMaterial(scene, "grey", vec3(0.7f));
  Mesh mesh;
  mesh.name = "corner";
  mesh.positions = {vec3(-1, 0, -1), vec3(0, 0, -1), vec3(0, 0, 1), vec3(-1, 0, 1),
                    vec3(0, 1, -1), vec3(0, 1, 1)};
  mesh.indices = {0, 2, 1, 0, 3, 2, 1, 2, 5, 1, 5, 4};  // floor: 0 and 1, wall: 2 and 3
  addMesh(scene, std::move(mesh), material);
  addLight(scene, vec3(5, 3, 0), 0.1f);
  scene.finalize();
  const VertexRings rings(scene);
  std::vector<uint32_t> neighbours;
  rings.neighbours(1, neighbours);
  EXPECT_EQ(neighbours, (std::vector<uint32_t>{0, 2}));  // sharing a vertex with triangle 1
  const dvec3 centre(5, 3, 0), eye(-4, 0.5, 0.2);
  PixelBasis f;
  f.primitive = 1;
  f.p = dvec3(-1e-4, 1e-6, 0.1);  // in front of the wall
  EXPECT_EQ(capCrossings(scene, neighbours, f, centre, eye), 0);
  f.p = dvec3(1e-6, 1e-6, 0.1);  // just past its plane
  EXPECT_EQ(capCrossings(scene, neighbours, f, centre, eye), -1);
}

}  // namespace test_exact_centre_shift
}  // namespace penumbra
