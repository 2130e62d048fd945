#include "shadows/shadowmap/light_frustum_stencil.h"

#include <array>

#include "core/timer.h"
#include "raster/rasterizer.h"
#include "raster/triangle_setup.h"

namespace penumbra {

Image<int32_t> lightFrustumStencil(const Light& light, const LightFace& face, const View& view,
                                   const EyeBuffers& eye, Stats& stats, bool simd) {
  PassTimer timer(stats, "light frustum");
  const dvec3 apex(light.center);
  const dvec3 right = glm::normalize(glm::cross(face.axis, face.up));
  const dvec3 up = glm::cross(right, face.axis);
  const double t = face.tan_half * (1.0 + kStencilFrustumMargin);
  // The pyramid from the apex to infinity: four edge directions (homogeneous w = 0, as shadow
  // volumes are extruded: Everitt & Kilgard 2002), four side triangles through the apex and the
  // cap at infinity. No near cap: the apex is a point.
  const std::array<dvec3, 4> dir = {face.axis + t * (-right - up), face.axis + t * (right - up),
                                    face.axis + t * (right + up), face.axis + t * (-right + up)};
  ClipTriangles volume;
  const uint32_t a = volume.addVertex(view.toClip(vec4(vec3(apex), 1.0f)));
  std::array<uint32_t, 4> d;
  for (int i = 0; i < 4; ++i) d[i] = volume.addVertex(view.toClip(vec4(vec3(dir[i]), 0.0f)));
  // Each polygon's front side faces out of the volume (rasterizeStencil's payload convention):
  // counter-clockwise seen from outside, like a mesh's front faces. Decided from stand-ins at
  // unit distance along the directions against a point inside, so no ordering is assumed.
  const dvec3 inside = apex + 0.5 * face.axis;
  const auto add = [&](uint32_t i0, const dvec3& p0, uint32_t i1, const dvec3& p1, uint32_t i2,
                       const dvec3& p2) {
    const bool outward = glm::dot(glm::cross(p1 - p0, p2 - p0), p0 - inside) > 0.0;
    if (outward)
      volume.add(i0, i1, i2, 1, kZFail);
    else
      volume.add(i0, i2, i1, 1, kZFail);
  };
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    add(a, apex, d[i], apex + dir[i], d[j], apex + dir[j]);
  }
  add(d[0], apex + dir[0], d[1], apex + dir[1], d[2], apex + dir[2]);
  add(d[0], apex + dir[0], d[2], apex + dir[2], d[3], apex + dir[3]);

  Image<int32_t> stencil(eye.depth.depth.width(), eye.depth.depth.height(), 0);
  StencilOptions options;
  options.simd = simd;
  rasterizeStencil(volume, eye.depth, stencil, stats, options);
  return stencil;
}

}  // namespace penumbra
