#include "render/shading.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"
#include "render/shading_reuse.h"

namespace penumbra {
namespace {

// A material with what every pixel would otherwise recompute: ambient x albedo, and the
// specular exponent as an integer when it is one (almost always), so (n.h)^s is a few
// multiplications instead of std::pow's exp/log (results differ from pow by a few ulps).
struct MaterialShading {
  vec3 albedo{0.0f};
  vec3 specular{0.0f};
  vec3 ambient{0.0f};  // scene ambient x albedo
  bool has_specular = false;
  int integer_exponent = -1;  // shininess when it is an integer in [0, kMaxIntegerExponent]
  float shininess = 0.0f;
};

constexpr int kMaxIntegerExponent = 1024;

float specularPower(float n_dot_h, const MaterialShading& m) {
  if (m.integer_exponent < 0) return std::pow(n_dot_h, m.shininess);
  float result = 1.0f, base = n_dot_h;
  for (int e = m.integer_exponent; e != 0; e >>= 1) {
    if (e & 1) result *= base;
    base *= base;
  }
  return result;
}

struct LightShading {
  vec3 center{0.0f};
  vec3 radiance{0.0f};            // colour x intensity
  const float* visibility = nullptr;  // null: unshadowed
};

// What shading needs of one triangle, gathered once per run of pixels showing it (pixels of a
// row mostly repeat their neighbour's triangle, so this is rarely recomputed).
struct TriangleShading {
  vec3 a{0.0f}, e0{0.0f}, e1{0.0f};  // vertex 0 and the two edges from it
  // Barycentrics of p: v = k11 dot(p - a, e0) - k01 dot(p - a, e1), w = k00 dot(p - a, e1) -
  // k01 dot(p - a, e0): the Gram matrix's inverse, premultiplied once per triangle.
  float k00 = 0, k01 = 0, k11 = 0;
  const vec3* corners = nullptr;  // 3 shading normals, or null: use the geometric normal
  vec3 geometric{0.0f, 1.0f, 0.0f};  // unit
  const MaterialShading* material = nullptr;
};

TriangleShading gatherTriangle(const Scene& scene, const std::vector<MaterialShading>& materials,
                               uint32_t primitive) {
  const auto [mesh_index, triangle] = scene.locateTriangle(primitive);
  const Mesh& mesh = scene.meshes[mesh_index];
  TriangleShading t;
  t.a = mesh.vertex(triangle, 0);
  t.e0 = mesh.vertex(triangle, 1) - t.a;
  t.e1 = mesh.vertex(triangle, 2) - t.a;
  const float d00 = glm::dot(t.e0, t.e0), d01 = glm::dot(t.e0, t.e1), d11 = glm::dot(t.e1, t.e1);
  const float denominator = d00 * d11 - d01 * d01;
  // Degenerate triangles (no area) shade with their first corner's normal.
  const float inv_denominator =
      denominator > 1e-30f * std::max(1.0f, d00 * d11) ? 1.0f / denominator : 0.0f;
  t.k00 = d00 * inv_denominator;
  t.k01 = d01 * inv_denominator;
  t.k11 = d11 * inv_denominator;
  const vec3 n = glm::cross(t.e0, t.e1);
  const float n_length = glm::length(n);
  if (n_length > 0.0f) t.geometric = n / n_length;
  if (mesh.corner_normals.size() == mesh.indices.size())
    t.corners = &mesh.corner_normals[size_t(triangle) * 3];
  t.material = &materials[mesh.material];
  return t;
}

// Shading normal at p: corner normals interpolated with barycentrics clamped to the triangle
// (the unprojected point is on the triangle only up to depth rounding, and a point just outside
// must not extrapolate), flipped to the side the eye sees. That side is decided by the
// geometric normal: an interpolated normal may lean away from the eye near a silhouette while
// the face itself is front-facing. The clamped weights are not divided by their sum: the
// normalisation that follows removes any common scale.
vec3 shadingNormal(const TriangleShading& t, const vec3& p, const vec3& ray) {
  vec3 n = t.geometric;
  if (t.corners != nullptr) {
    const vec3 ep = p - t.a;
    const float dp0 = glm::dot(ep, t.e0), dp1 = glm::dot(ep, t.e1);
    float v = t.k11 * dp0 - t.k01 * dp1;
    float w = t.k00 * dp1 - t.k01 * dp0;
    float u = 1.0f - v - w;
    u = std::max(u, 0.0f);
    v = std::max(v, 0.0f);
    w = std::max(w, 0.0f);
    if (!(u + v + w > 0.0f)) u = 1.0f;
    const vec3 interpolated = u * t.corners[0] + v * t.corners[1] + w * t.corners[2];
    const float length2 = glm::dot(interpolated, interpolated);
    if (length2 > 1e-20f) n = interpolated * (1.0f / std::sqrt(length2));
  }
  // The eye is at -ray from p: the eye sees the side the geometric normal points to when
  // dot(geometric, -ray) >= 0.
  return glm::dot(t.geometric, ray) > 0.0f ? -n : n;
}

// Lambert diffuse + Blinn-Phong specular of every light, times its visibility, plus ambient.
// `ray` runs from the eye to p (any length).
vec3 shadePoint(const MaterialShading& m, const vec3& n, const vec3& p, const vec3& ray,
                const std::vector<LightShading>& lights, size_t pixel) {
  vec3 v(0.0f);
  if (m.has_specular) v = -ray * (1.0f / std::sqrt(glm::dot(ray, ray)));
  vec3 color = m.ambient;
  for (const LightShading& light : lights) {
    const float vis = light.visibility ? light.visibility[pixel] : 1.0f;
    if (!(vis > 0.0f)) continue;
    const vec3 to_light = light.center - p;
    const float distance2 = glm::dot(to_light, to_light);
    if (!(distance2 > 0.0f)) continue;
    const float n_dot_to_light = glm::dot(n, to_light);
    if (n_dot_to_light <= 0.0f) continue;  // facing away: neither diffuse nor specular
    const float inv_distance = 1.0f / std::sqrt(distance2);
    vec3 reflected = m.albedo * (n_dot_to_light * inv_distance);
    if (m.has_specular) {
      const vec3 h = to_light * inv_distance + v;
      const float h_length2 = glm::dot(h, h);
      const float n_dot_h =
          h_length2 > 0.0f ? std::max(0.0f, glm::dot(n, h)) * (1.0f / std::sqrt(h_length2)) : 0.0f;
      reflected += m.specular * specularPower(n_dot_h, m);
    }
    color += reflected * light.radiance * std::min(vis, 1.0f);
  }
  return color;
}

void checkInputs(const Scene& scene, const View& view, const EyeBuffers& eye,
                 const std::vector<const Image<float>*>& visibility) {
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

// Shades every pixel of `out` (already view-sized); `fill_background` false when `out` already
// holds the background colour everywhere.
void shadePixels(const Scene& scene, const View& view, const EyeBuffers& eye,
                 const std::vector<const Image<float>*>& visibility, Image<vec3>& out,
                 bool fill_background) {
  std::vector<MaterialShading> materials(scene.materials.size());
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& m = scene.materials[i];
    MaterialShading& s = materials[i];
    s.albedo = m.albedo;
    s.specular = m.specular;
    s.ambient = scene.settings.ambient * m.albedo;
    s.has_specular = m.specular != vec3(0.0f);
    s.shininess = m.shininess;
    if (m.shininess >= 0.0f && m.shininess <= float(kMaxIntegerExponent) &&
        m.shininess == std::floor(m.shininess))
      s.integer_exponent = int(m.shininess);
  }
  std::vector<LightShading> lights(scene.lights.size());
  for (size_t i = 0; i < lights.size(); ++i) {
    lights[i].center = scene.lights[i].center;
    lights[i].radiance = scene.lights[i].color * scene.lights[i].intensity;
    lights[i].visibility = visibility[i] ? visibility[i]->data() : nullptr;
  }
  const uint64_t triangle_count =
      scene.triangle_offsets.empty() ? 0 : scene.triangle_offsets.back();
  const Image<float>& depth = eye.depth.depth;
  const vec3 background = scene.settings.background;
  const vec3 eye_position = view.eye;
  // World-space direction of the view ray through screen point (sx, sy), scaled so that the
  // point at reversed-Z depth d is eye + direction * (near / d) (core/view.h): affine in sx, sy.
  const mat3 rotation(view.inverse_view);
  const float sx_scale = 2.0f / (float(view.width) * view.projection[0][0]);
  const float sy_scale = -2.0f / (float(view.height) * view.projection[1][1]);
  const vec3 ray_dx = rotation * vec3(sx_scale, 0.0f, 0.0f);
  const vec3 ray_dy = rotation * vec3(0.0f, sy_scale, 0.0f);
  const vec3 ray_origin = rotation * vec3(-1.0f / view.projection[0][0], 1.0f / view.projection[1][1], -1.0f);
  parallelFor(size_t(view.height), [&](size_t row) {
    const int y = int(row);
    vec3* out_row = out.row(y);
    const float* depth_row = depth.row(y);
    const uint32_t* id_row = eye.primitive.row(y);
    const vec3 row_ray = ray_origin + ray_dy * (float(y) + 0.5f);
    const size_t row_pixel = size_t(y) * size_t(view.width);
    uint32_t cached_id = kNoPrimitive;
    TriangleShading triangle;
    for (int x = 0; x < view.width; ++x) {
      const uint32_t id = id_row[x];
      // Depth is reversed-Z (core/view.h): > 0 wherever a triangle was drawn.
      if (id == kNoPrimitive || !(depth_row[x] > 0.0f)) {
        if (fill_background) out_row[x] = background;
        continue;
      }
      if (id != cached_id) {
        PENUMBRA_CHECK(id < triangle_count, "shading: pixel ({}, {}) names triangle {} of {}",
                       x, y, id, triangle_count);
        triangle = gatherTriangle(scene, materials, id);
        cached_id = id;
      }
      const vec3 ray = row_ray + ray_dx * (float(x) + 0.5f);
      const vec3 p = eye_position + ray * (view.near_plane / depth_row[x]);
      const vec3 n = shadingNormal(triangle, p, ray);
      out_row[x] = shadePoint(*triangle.material, n, p, ray, lights, row_pixel + size_t(x));
    }
  });
}

}  // namespace

Image<vec3> shadeFrame(const Scene& scene, const View& view, const EyeBuffers& eye,
                       const std::vector<const Image<float>*>& visibility) {
  checkInputs(scene, view, eye, visibility);
  Image<vec3> out(view.width, view.height, scene.settings.background);
  shadePixels(scene, view, eye, visibility, out, false);
  return out;
}

void shadeFrameInto(const Scene& scene, const View& view, const EyeBuffers& eye,
                    const std::vector<const Image<float>*>& visibility, Image<vec3>& out) {
  checkInputs(scene, view, eye, visibility);
  if (out.width() != view.width || out.height() != view.height)
    out.resize(view.width, view.height);
  shadePixels(scene, view, eye, visibility, out, true);
}

}  // namespace penumbra
