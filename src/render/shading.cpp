#include "render/shading.h"

#include <algorithm>
#include <memory>

#include "core/error.h"
#include "core/parallel.h"
#include "render/shading_kernel.h"
#include "render/shading_reuse.h"

namespace penumbra {
namespace {

void checkInputs(const Scene& scene, const View& view, const EyeBuffers& eye,
                 const std::vector<const Image<float>*>& visibility,
                 const std::vector<const ChannelVisibility*>& channels) {
  const Image<float>& depth = eye.depth.depth;
  PENUMBRA_CHECK(depth.width() == view.width && depth.height() == view.height &&
                     eye.primitive.width() == view.width && eye.primitive.height() == view.height,
                 "shading: eye buffers ({}x{} depth, {}x{} ids) do not match the {}x{} view",
                 depth.width(), depth.height(), eye.primitive.width(), eye.primitive.height(),
                 view.width, view.height);
  PENUMBRA_CHECK(visibility.size() == scene.lights.size(),
                 "shading: {} visibility buffers for {} lights", visibility.size(),
                 scene.lights.size());
  for (size_t i = 0; i < visibility.size(); ++i) {
    PENUMBRA_CHECK(!visibility[i] || (visibility[i]->width() == view.width &&
                                      visibility[i]->height() == view.height),
                   "shading: visibility of light {} is {}x{}, the view is {}x{}", i,
                   visibility[i]->width(), visibility[i]->height(), view.width, view.height);
  }
  PENUMBRA_CHECK(channels.empty() || channels.size() == scene.lights.size(),
                 "shading: {} channel visibilities for {} lights", channels.size(),
                 scene.lights.size());
  for (size_t i = 0; i < channels.size(); ++i) {
    if (channels[i] == nullptr || (*channels[i])[0].empty()) continue;
    for (const Image<float>& channel : *channels[i]) {
      PENUMBRA_CHECK(channel.width() == view.width && channel.height() == view.height,
                     "shading: a channel visibility of light {} is {}x{}, the view is {}x{}", i,
                     channel.width(), channel.height(), view.width, view.height);
    }
  }
  const uint64_t triangle_count =
      scene.triangle_offsets.empty() ? 0 : scene.triangle_offsets.back();
  PENUMBRA_CHECK(scene.meshes.empty() || triangle_count == scene.triangleCount(),
                 "shading: scene '{}' is not finalized (triangle offsets missing)", scene.name);
  for (const Mesh& mesh : scene.meshes) {
    PENUMBRA_CHECK(mesh.material < scene.materials.size(),
                   "shading: mesh '{}' uses material {} but the scene has {}", mesh.name,
                   mesh.material, scene.materials.size());
  }
}

// Shades every pixel of `out` (view-sized), background included, row by row
// (render/shading_kernel.h).
void shadePixels(const Scene& scene, const View& view, const EyeBuffers& eye,
                 const std::vector<const Image<float>*>& visibility,
                 const std::vector<const ChannelVisibility*>& channels, Image<vec3>& out,
                 bool simd, ShadingTriangleTable* kept) {
  ShadingFrame frame;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const vec3 radiance = lightRadiance(scene.lights[i]);
    const ChannelVisibility* per_channel = i < channels.size() ? channels[i] : nullptr;
    if (per_channel != nullptr && !(*per_channel)[0].empty()) {
      for (int c = 0; c < 3; ++c) {
        ShadingLight light;
        light.center = scene.lights[i].center;
        light.radiance = vec3(0.0f);
        light.radiance[c] = radiance[c];
        light.visibility = (*per_channel)[size_t(c)].data();
        frame.lights.push_back(light);
      }
      continue;
    }
    ShadingLight light;
    light.center = scene.lights[i].center;
    light.radiance = radiance;
    light.visibility = visibility[i] ? visibility[i]->data() : nullptr;
    frame.lights.push_back(light);
  }
  frame.depth = eye.depth.depth.data();
  frame.primitive = eye.primitive.data();
  frame.width = view.width;
  frame.eye = view.eye;
  frame.near_plane = view.near_plane;
  frame.background = scene.settings.background;
  // World-space direction of the view ray through screen point (sx, sy), scaled so that the
  // point at reversed-Z depth d is eye + direction * (near / d) (core/view.h): affine in sx, sy.
  const mat3 rotation(view.inverse_view);
  const float sx_scale = 2.0f / (float(view.width) * view.projection[0][0]);
  const float sy_scale = -2.0f / (float(view.height) * view.projection[1][1]);
  frame.ray_dx = rotation * vec3(sx_scale, 0.0f, 0.0f);
  frame.ray_dy = rotation * vec3(0.0f, sy_scale, 0.0f);
  frame.ray_origin =
      rotation * vec3(-1.0f / view.projection[0][0], 1.0f / view.projection[1][1], -1.0f);
  std::unique_ptr<ShadingTriangleTable> own;
  if (kept == nullptr) own = std::make_unique<ShadingTriangleTable>(scene);
  ShadingTriangleTable& triangles = kept != nullptr ? *kept : *own;
  // Bands of rows per task: enough work to amortise a task, enough bands (68 at 1080 rows) to
  // balance the workers.
  constexpr int kRowsPerTask = 16;
  parallelFor(size_t((view.height + kRowsPerTask - 1) / kRowsPerTask), [&](size_t band) {
    const int y_end = std::min(view.height, int(band + 1) * kRowsPerTask);
    for (int y = int(band) * kRowsPerTask; y < y_end; ++y)
      shadeRow(frame, y, triangles, out.row(y), simd);
  });
}

}  // namespace

Image<vec3> shadeFrame(const Scene& scene, const View& view, const EyeBuffers& eye,
                       const std::vector<const Image<float>*>& visibility) {
  Image<vec3> out;
  shadeFrameInto(scene, view, eye, visibility, out);
  return out;
}

void shadeFrameInto(const Scene& scene, const View& view, const EyeBuffers& eye,
                    const std::vector<const Image<float>*>& visibility, Image<vec3>& out,
                    bool simd, const std::vector<const ChannelVisibility*>& channels,
                    ShadingTriangleTable* triangles) {
  checkInputs(scene, view, eye, visibility, channels);
  if (out.width() != view.width || out.height() != view.height)
    out.resize(view.width, view.height);
  shadePixels(scene, view, eye, visibility, channels, out, simd, triangles);
}

}  // namespace penumbra
