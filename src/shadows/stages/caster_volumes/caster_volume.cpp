#include "shadows/stages/caster_volumes/caster_volume.h"

#include <algorithm>
#include <array>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {
namespace {

// Smallest signed distance of the box's corners to a plane (n, d): dot(n, p) + d, taken at the
// box's "n-vertex" (the corner farthest against the normal).
double minDistance(const dvec3& n, double d, const Bounds3& box) {
  const dvec3 near_corner(n.x >= 0 ? box.min.x : box.max.x, n.y >= 0 ? box.min.y : box.max.y,
                          n.z >= 0 ? box.min.z : box.max.z);
  return glm::dot(n, near_corner) + d;
}

Bounds3 inflated(Bounds3 b, float r) {
  if (b.empty() || !(r > 0.0f)) return b;
  b.min -= vec3(r);
  b.max += vec3(r);
  return b;
}

}  // namespace

std::string volumeModeName(VolumeMode mode) {
  switch (mode) {
    case VolumeMode::Auto: return "auto";
    case VolumeMode::ZPass: return "zpass";
    case VolumeMode::ZFail: return "zfail";
  }
  return "unknown";
}

bool mayContainNearPlane(const View& view, const vec3& light, const Bounds3& caster) {
  if (caster.empty()) return false;
  // Near-plane rectangle in world space, grown by 1 % so rounding cannot hide a touch.
  const double hw = 1.01 * view.near_plane / view.projection[0][0];
  const double hh = 1.01 * view.near_plane / view.projection[1][1];
  const dmat4 to_world(view.inverse_view);
  std::array<dvec3, 5> hull;  // four corners, then the light
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i)
    hull[i] = dvec3(to_world * dvec4(sx[i] * hw, sy[i] * hh, -double(view.near_plane), 1.0));
  hull[4] = dvec3(light);
  const dvec3 centre = (hull[0] + hull[1] + hull[2] + hull[3] + hull[4]) / 5.0;

  // Separating axes of the box: the hull lies entirely beyond one of its faces.
  for (int axis = 0; axis < 3; ++axis) {
    bool all_below = true, all_above = true;
    for (const dvec3& p : hull) {
      all_below &= p[axis] < caster.min[axis];
      all_above &= p[axis] > caster.max[axis];
    }
    if (all_below || all_above) return false;
  }
  // Separating planes of the hull: the rectangle's plane and the four planes through the light
  // and a rectangle edge, each oriented so the hull's centre is on the negative (inner) side;
  // the box is separated when it lies wholly on the positive side.
  auto separates = [&](const dvec3& a, const dvec3& b, const dvec3& c) {
    dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    if (!(len > 1e-12)) return false;  // light on the near plane: no plane, assume overlap
    n /= len;
    double d = -glm::dot(n, a);
    if (glm::dot(n, centre) + d > 0) {
      n = -n;
      d = -d;
    }
    return minDistance(n, d, caster) > 0;
  };
  if (separates(hull[0], hull[1], hull[2])) return false;
  for (int i = 0; i < 4; ++i)
    if (separates(hull[4], hull[i], hull[(i + 1) % 4])) return false;
  return true;
}

CasterVolume casterVolume(const Scene& scene, size_t m, const EyeBuffers& eye, const vec3& centre,
                          const View& view, VolumeMode mode, CasterPolicy policy, float margin) {
  return casterVolume(scene, m, findSilhouette(scene.meshes[m], scene.adjacency[m], centre, policy),
                      eye, centre, view, mode, margin);
}

CasterVolume casterVolume(const Scene& scene, size_t m, Silhouette silhouette,
                          const EyeBuffers& eye, const vec3& centre, const View& view,
                          VolumeMode mode, float margin) {
  PENUMBRA_CHECK(eye.mesh_vertex_base.size() == scene.meshes.size(),
                 "the eye buffers hold the vertices of {} meshes but the scene has {}",
                 eye.mesh_vertex_base.size(), scene.meshes.size());
  const Mesh& mesh = scene.meshes[m];
  CasterVolume v;
  v.silhouette = std::move(silhouette);
  v.zfail = mode == VolumeMode::ZFail ||
            (mode == VolumeMode::Auto &&
             mayContainNearPlane(view, centre, inflated(mesh.bounds(), margin)));
  v.finite = eye.mesh_vertex_base[m];
  return v;
}

void appendExtrudedVertices(const Mesh& mesh, const vec3& centre, const View& view,
                            CasterVolume& volume, ClipTriangles& out) {
  const size_t n = mesh.positions.size();
  volume.infinite = out.appendVertices(n);
  vec4* extruded = out.ownVertex(volume.infinite);
  parallelFor((n + 4095) / 4096, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * 4096);
    for (size_t i = chunk * 4096; i < end; ++i)
      extruded[i] = view.toClip(vec4(mesh.positions[i] - centre, 0.0f));
  });
}

}  // namespace penumbra
