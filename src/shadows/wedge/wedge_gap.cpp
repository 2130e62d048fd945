#include "shadows/wedge/wedge_gap.h"

#include <cmath>

#include "shadows/wedge/wedge_sides.h"

namespace penumbra::wedge_detail {
namespace {

// A front ray must enter the other wedge's notch side at least this fraction of the fan's
// opening angle (the sine between the two front rays): closer, the notch is rounding noise and
// the cone would be degenerate.
constexpr double kMinOpening = 1e-3;

Plane negated(const Plane& p) { return Plane{-p.n, -p.d}; }

// The plane through v holding unit directions u0 and u1, oriented so that `inside` is on its
// positive side; false when u0 and u1 are parallel. The two rays of a small light are close
// (their angle is about r / distance), so the normal is cross(u0, u1 - u0): the difference is
// nearly exact, where cross(u0, u1) would cancel and keep only 1e-16 / angle of relative
// precision, a visible step in s across the shared planes for tiny lights.
bool planeThroughRays(const dvec3& v, const dvec3& u0, const dvec3& u1, const dvec3& inside,
                      Plane& plane) {
  dvec3 n = glm::cross(u0, u1 - u0);
  const double len = glm::length(n);
  if (!(len > kParallelSin) || !std::isfinite(len)) return false;
  n /= len;
  if (glm::dot(n, inside) < 0.0) n = -n;
  plane = Plane{n, -glm::dot(n, v)};
  return true;
}

}  // namespace

bool gapWedge(const Wedge& in, uint32_t in_wedge, const Wedge& out, uint32_t out_wedge,
              uint32_t connector, const dvec3& light_center, Wedge& gap) {
  const dvec3 v = in.b;
  const dvec3& front_l = in.ray_front_right;
  const dvec3& front_r = out.ray_front_left;
  const dvec3& back_l = in.ray_back_right;
  const dvec3& back_r = out.ray_back_left;
  const Plane left = negated(in.right), right = negated(out.left);
  // The notch is where both end planes have the wedges outside: it exists when each front ray
  // leaves its own wedge into the other wedge's outside (convex corner). At a concave corner
  // the front rays lie inside the other wedge's end plane: the wedges overlap, there is no
  // notch to fill.
  const double opening = glm::length(glm::cross(front_l, front_r - front_l));
  if (!(opening > kParallelSin)) return false;
  if (!(glm::dot(left.n, front_r) > kMinOpening * opening &&
        glm::dot(right.n, front_l) > kMinOpening * opening))
    return false;
  // Both planes must have the hard direction v - c inside and so the light centre outside, as
  // every wedge's front and back planes do: the front ray fan on the lit side of it, the back
  // ray fan on the umbra side.
  const dvec3 hard = v - light_center;
  Plane front, back;
  if (!planeThroughRays(v, front_l, front_r, hard, front) ||
      !planeThroughRays(v, back_l, back_r, front_l + front_r, back))
    return false;
  if (!(glm::dot(front.n, hard) > 0.0 && glm::dot(back.n, hard) > 0.0 &&
        glm::dot(back.n, front_l) > 0.0 && glm::dot(back.n, front_r) > 0.0 &&
        glm::dot(front.n, back_l + back_r) > 0.0))
    return false;
  // Equation (3)'s t_l, t_r are distances along edge_dir; with no edge, a direction making the
  // same angle with both side planes weighs the two sides by their plane distances.
  const dvec3 across = left.n - right.n;
  const double across_len = glm::length(across);
  if (!(across_len > kParallelSin)) return false;

  Wedge w;
  w.va = w.vb = in.vb;
  w.a = w.b = v;
  w.front = front;
  w.back = back;
  w.left = left;
  w.right = right;
  w.dir_left = in.dir_right;
  w.dir_right = out.dir_left;
  w.edge_dir = across / across_len;
  w.normal = -front.n;
  w.ray_front_left = front_l;
  w.ray_back_left = back_l;
  w.ray_front_right = front_r;
  w.ray_back_right = back_r;
  w.unit_edge = connector;
  w.left_wedge = in_wedge;
  w.right_wedge = out_wedge;
  gap = w;
  return true;
}

}  // namespace penumbra::wedge_detail
