#pragma once
// Self-shadowing by facing, and the per-pixel resolve of a technique's visibility built on it.
#include <cstdint>

#include "core/image.h"
#include "core/parallel.h"
#include "core/view.h"
#include "raster/depth_buffer.h"
#include "scene/light.h"
#include "scene/scene.h"

namespace penumbra {

// A visible point whose own triangle faces away from the whole light receives none of it: the
// surface shadows itself. "Faces away": the light sphere lies entirely on the far side of the
// triangle's plane from the side the eye sees; for a point light, the centre lies strictly on
// that side. Shadow volumes only get this right up to rounding where a silhouette quad grazes
// the surface along the terminator; the oracle decides it exactly, from the triangle's
// vertices, and so does this.
//
// Decided per triangle and remembered for the last one asked: neighbouring pixels mostly see
// the same triangle, so a row of pixels needs a handful of decisions. Copy it per row (or per
// thread): the memory is not shared.
class FacingAway {
 public:
  FacingAway(const Scene& scene, const Light& light, const View& view)
      : scene_(&scene), eye_(view.eye), centre_(light.center), radius_(light.radius) {}
  // Inline: called for every pixel, and nearly always answered from the remembered triangle.
  bool operator()(uint32_t primitive) {
    return primitive == cached_ ? away_ : decide(primitive);
  }

 private:
  bool decide(uint32_t primitive);

  const Scene* scene_;
  dvec3 eye_, centre_;
  double radius_;
  uint32_t cached_ = kNoPrimitive;
  bool away_ = false;
};

// Writes every pixel of `visibility` (sized like the eye buffers): 1 for the background, 0
// where the visible triangle faces away from the light, else pixel(x, y), the technique's own
// answer. One pass over the buffers, rows in parallel.
template <class PixelVisibility>
void resolveVisibility(const Scene& scene, const Light& light, const View& view,
                       const EyeBuffers& eye, Image<float>& visibility, PixelVisibility&& pixel) {
  const int width = eye.primitive.width(), height = eye.primitive.height();
  visibility.resizeForOverwrite(width, height);
  const FacingAway facing_away(scene, light, view);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    FacingAway away = facing_away;
    const uint32_t* ids = eye.primitive.row(y);
    float* out = visibility.row(y);
    for (int x = 0; x < width; ++x) {
      const uint32_t id = ids[x];
      out[x] = id == kNoPrimitive ? 1.0f : (away(id) ? 0.0f : pixel(x, y));
    }
  });
}

}  // namespace penumbra
