#pragma once
// Self-shadowing by facing, and the per-pixel resolve of a technique's visibility built on it.
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

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
// Decided once per triangle, the first time a pixel asks, and remembered in a table shared by
// the threads of one resolve (a byte per scene triangle; the answer does not depend on who
// decides it first). Remembering only the last triangle asked is not enough: a row crossing
// the finely tessellated columns of `columns` meets a new triangle every few pixels, and the
// decisions become a visible share of the soft-shadow frame (bench/README.md).
class FacingAway {
 public:
  FacingAway(const Scene& scene, const Light& light, const View& view)
      : scene_(&scene), eye_(view.eye), centre_(light.center), radius_(light.radius),
        known_(scene.triangleCount()) {}
  bool operator()(uint32_t primitive) const { return state(primitive) == kAway; }
  // The opposite case, with a margin: the whole light lies in front of the triangle, on the
  // side the eye sees, farther from its plane than radius * (1 + kClearMargin) (for a point
  // light, strictly in front). No sample of the light is behind the surface then, whatever the
  // point on it the rays start from (RayStart::intoSurface), which the exact soft shadow
  // volumes use to skip setting up pixels no edge reaches.
  bool clearOfLight(uint32_t primitive) const { return state(primitive) == kClear; }
  static constexpr double kClearMargin = 1e-4;

 private:
  static constexpr uint8_t kUnknown = 0, kAway = 1, kAcross = 2, kClear = 3;
  uint8_t state(uint32_t primitive) const {
    const uint8_t known = known_[primitive].load(std::memory_order_relaxed);
    return known != kUnknown ? known : decide(primitive);
  }
  uint8_t decide(uint32_t primitive) const;

  const Scene* scene_;
  dvec3 eye_, centre_;
  double radius_;
  mutable std::vector<std::atomic<uint8_t>> known_;  // value-initialized: kUnknown
};

// The rule every resolved pixel follows: 1 for the background, 0 where the visible triangle
// `id` faces away from the light, else `value`, the technique's own answer (read only then).
template <class PixelValue>
inline float resolvedPixel(const FacingAway& away, uint32_t id, PixelValue&& value) {
  return id == kNoPrimitive ? 1.0f : (away(id) ? 0.0f : value());
}

// Writes every pixel of `visibility` (sized like the eye buffers) by resolvedPixel with
// pixel(x, y). One pass over the buffers, rows in parallel. `away` may be one the caller has
// used already: its decisions are kept per triangle.
template <class PixelVisibility>
void resolveVisibility(const FacingAway& away, const EyeBuffers& eye, Image<float>& visibility,
                       PixelVisibility&& pixel) {
  const int width = eye.primitive.width(), height = eye.primitive.height();
  visibility.resizeForOverwrite(width, height);
  parallelFor(size_t(height), [&](size_t row) {
    const int y = int(row);
    const uint32_t* ids = eye.primitive.row(y);
    float* out = visibility.row(y);
    for (int x = 0; x < width; ++x) {
      out[x] = resolvedPixel(away, ids[x], [&] { return pixel(x, y); });
    }
  });
}

// The same with a FacingAway of its own.
template <class PixelVisibility>
void resolveVisibility(const Scene& scene, const Light& light, const View& view,
                       const EyeBuffers& eye, Image<float>& visibility, PixelVisibility&& pixel) {
  const FacingAway away(scene, light, view);
  resolveVisibility(away, eye, visibility, std::forward<PixelVisibility>(pixel));
}

}  // namespace penumbra
