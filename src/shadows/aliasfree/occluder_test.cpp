#include "shadows/aliasfree/occluder_test.h"

#include <cmath>

namespace penumbra {
namespace {

// The first nonzero component's sign; the tie rule's owner test (occluder_test.h).
bool firstNonzeroPositive(const dvec3& v) {
  if (v.x != 0.0) return v.x > 0.0;
  if (v.y != 0.0) return v.y > 0.0;
  return v.z > 0.0;
}

}  // namespace

std::optional<OccluderTest> makeOccluderTest(const vec3& a, const vec3& b, const vec3& c,
                                             const vec3& light) {
  // Float vertices minus a float centre: exact in double for any two floats within 2^29 of
  // each other's magnitude, so both triangles of a shared edge see the same relative vertices.
  const dvec3 l(light);
  const dvec3 pa = dvec3(a) - l, pb = dvec3(b) - l, pc = dvec3(c) - l;
  if (!std::isfinite(pa.x + pa.y + pa.z + pb.x + pb.y + pb.z + pc.x + pc.y + pc.z)) {
    return std::nullopt;
  }
  dvec3 edges[3] = {glm::cross(pa, pb), glm::cross(pb, pc), glm::cross(pc, pa)};
  // Which way abc winds as seen from L: the sign of the triple product. Zero: edge-on.
  const double orientation = glm::dot(edges[0], pc);
  if (!(orientation != 0.0) || !std::isfinite(orientation)) return std::nullopt;
  dvec3 normal = glm::cross(dvec3(b) - dvec3(a), dvec3(c) - dvec3(a));
  double offset = glm::dot(normal, pa);  // = n . (a - L): L's side of the plane is offset's sign
  if (!(offset != 0.0) || !std::isfinite(offset)) return std::nullopt;
  if (offset < 0.0) {
    normal = -normal;
    offset = -offset;
  }
  OccluderTest t;
  for (int i = 0; i < 3; ++i) {
    // Negation is exact, so a shared edge's two normals stay exact negations of each other.
    if (orientation < 0.0) edges[i] = -edges[i];
    t.edge[i][0] = edges[i].x;
    t.edge[i][1] = edges[i].y;
    t.edge[i][2] = edges[i].z;
    t.edge_ties[i] = firstNonzeroPositive(edges[i]);
  }
  t.plane[0] = normal.x;
  t.plane[1] = normal.y;
  t.plane[2] = normal.z;
  t.offset = offset;
  return t;
}

}  // namespace penumbra
