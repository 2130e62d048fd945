#pragma once
// Where the oracle's shadow rays start for a pixel: the pixel's depth-buffer point put back on
// the surface the eye pass says is visible there, and nudged off it toward the eye's side.
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "core/view.h"
#include "scene/scene.h"

namespace penumbra {

struct RayStart {
  dvec3 origin{0.0};
  dvec3 depth_point{0.0};   // the pixel's depth-buffer point (View::unproject) it came from
  dvec3 plane_point{0.0};   // a vertex of the visible triangle
  dvec3 plane_normal{0.0};  // unnormalised, on the side the eye sees; zero: no usable plane

  // The visible surface itself blocks a ray toward a point strictly on its far side: the
  // shaded point lies on it, so such a ray enters it at once. Decided exactly from the
  // triangle's own vertices, and those rays are never traced (an offset origin would let rays
  // from near an edge slip past the triangle). Shadow volumes make the same call: a face turned
  // away from the light is in shadow, a face exactly edge-on to it casts nothing.
  bool intoSurface(const dvec3& target) const {
    return glm::dot(plane_normal, target - plane_point) < 0.0;
  }
};

// How far, in pixel footprints (distance to the eye times the pixel angle at the image centre),
// an origin can lie from its pixel's depth-buffer point: the snap onto the visible triangle is
// at most 1 (ray_origin.cpp), the lift off it is float rounding, the fallback step 0.125. For
// techniques that cull by the depth buffer and then shade the oracle's points.
inline constexpr double kMaxOriginOffsetFootprints = 1.25;

// What start() derives from the visible triangle alone (its vertices, normals and edge
// directions: a dozen square roots), kept for the next pixel of the same triangle. A row
// crosses few triangles on most scenes, so a caller walking pixels in order keeps one of these
// per thread and passes it to every call; the answers are bit for bit those without it.
struct OriginTriangle {
  uint32_t primitive = 0xffffffffu;  // the triangle held, or none
  dvec3 a{0.0}, b{0.0}, c{0.0};
  dvec3 winding_normal{0.0};  // (b - a) x (c - a)
  dvec3 inward[3]{};          // unit in-plane normals of edges ab, bc, ca, into the triangle
  double length = 0.0;        // |winding_normal|
  double eye_side = 0.0;      // winding_normal . (eye - a)
  double extent = 0.0;        // longest edge
  double perimeter = 0.0;
};

class RayOrigins {
 public:
  RayOrigins(const Scene& scene, const View& view);

  // Triangles in the scene: valid ids are below this (see EyeBuffers::primitive).
  uint64_t triangleCount() const { return offsets_.back(); }

  // `primitive` is the pixel's global triangle id or kNoPrimitive; depth > 0. `triangle`
  // holds the last visible triangle's derived values (OriginTriangle).
  RayStart start(int x, int y, float depth, uint32_t primitive, OriginTriangle& triangle) const;
  RayStart start(int x, int y, float depth, uint32_t primitive) const {
    OriginTriangle triangle;
    return start(x, y, depth, primitive, triangle);
  }

  // Throws penumbra::Error naming the pixel when an eye pass's id is not a triangle of the
  // scene (kNoPrimitive is fine): checked once before the per-pixel work trusts them.
  void checkPrimitiveIds(const Image<uint32_t>& ids) const;

 private:
  void deriveTriangle(uint32_t primitive, OriginTriangle& triangle) const;

  const Scene& scene_;
  const View& view_;
  double pixel_angle_;             // radians per pixel at the image centre
  std::vector<uint64_t> offsets_;  // first global id of every mesh, then the total
};

// The point of triangle abc closest to q (Ericson, Real-Time Collision Detection, 5.1.5).
dvec3 closestPointOnTriangle(const dvec3& q, const dvec3& a, const dvec3& b, const dvec3& c);

}  // namespace penumbra
