// The scalar twin of shading_kernel_simd.cpp (same steps, same operation order) and the
// triangle records both read.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "raster/depth_buffer.h"
#include "render/shading_kernel.h"

namespace penumbra {
namespace {

// Written out so both twins sum in the same order: (x + y) + z, as glm::dot does.
inline float dot3(const vec3& a, const vec3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

// x86's packed max(a, 0), which the SIMD twin compiles to: a NaN gives 0.
inline float maxZero(float a) { return a > 0.0f ? a : 0.0f; }

float specularPower(float n_dot_h, const ShadingTriangle& t) {
  if (t.exponent < 0) return std::pow(n_dot_h, t.shininess);
  float result = 1.0f, base = n_dot_h;
  for (int32_t e = t.exponent; e != 0; e >>= 1) {
    if (e & 1) result *= base;
    base *= base;
  }
  return result;
}

}  // namespace

ShadingTriangleTable::ShadingTriangleTable(const Scene& scene)
    : scene_(scene),
      count_(scene.triangle_offsets.empty() ? 0 : scene.triangle_offsets.back()),
      slots_(new std::atomic<uint32_t>[count_]),
      records_(new ShadingTriangle[count_]) {
  // Global triangle ids are 32-bit (EyeBuffers::primitive): a slot holds any record's place.
  PENUMBRA_CHECK(count_ < uint64_t(UINT32_MAX) - kFirstRecord,
                 "shading: {} triangles are more than the table can number", count_);
}

const ShadingTriangle& ShadingTriangleTable::getSlow(uint32_t id, ShadingTriangle& scratch) {
  PENUMBRA_CHECK(id < count_, "shading: a pixel names triangle {} of {}", id, count_);
  uint32_t slot = kEmpty;
  if (slots_[id].compare_exchange_strong(slot, kBuilding, std::memory_order_acquire)) {
    const uint32_t place = used_.fetch_add(1, std::memory_order_relaxed);
    build(id, records_[place]);
    slots_[id].store(kFirstRecord + place, std::memory_order_release);
    return records_[place];
  }
  if (slot >= kFirstRecord) return records_[slot - kFirstRecord];
  build(id, scratch);  // another worker is building it: build a private copy meanwhile
  return scratch;
}

void ShadingTriangleTable::build(uint32_t id, ShadingTriangle& t) const {
  const Scene& scene = scene_;
  const auto [mesh_index, triangle] = scene.locateTriangle(id);
  const Mesh& mesh = scene.meshes[mesh_index];
  t.a = mesh.vertex(triangle, 0);
  const vec3 e0 = mesh.vertex(triangle, 1) - t.a;
  const vec3 e1 = mesh.vertex(triangle, 2) - t.a;
  const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const float denominator = d00 * d11 - d01 * d01;
  // Degenerate triangles (no area) shade with their first corner's normal: gv = gw = 0.
  const float inv_denominator =
      denominator > 1e-30f * std::max(1.0f, d00 * d11) ? 1.0f / denominator : 0.0f;
  t.gv = (e0 * d11 - e1 * d01) * inv_denominator;
  t.gw = (e1 * d00 - e0 * d01) * inv_denominator;
  const vec3 n = glm::cross(e0, e1);
  const float n_length = glm::length(n);
  t.geometric = n_length > 0.0f ? n / n_length : vec3(0.0f, 1.0f, 0.0f);
  if (mesh.corner_normals.size() == mesh.indices.size()) {
    const vec3* corners = &mesh.corner_normals[size_t(triangle) * 3];
    t.n0 = corners[0];
    t.n1 = corners[1];
    t.n2 = corners[2];
  } else {
    t.n0 = t.n1 = t.n2 = t.geometric;
  }
  // A zero normal (bad data) goes through the interpolation, which falls back to geometric.
  t.flat = t.n0 == t.n1 && t.n1 == t.n2 && glm::dot(t.n0, t.n0) > 1e-20f;
  const Material& m = scene.materials[mesh.material];
  t.albedo = m.albedo;
  t.specular = m.specular;
  t.ambient = scene.settings.ambient * m.albedo;
  t.has_specular = m.specular != vec3(0.0f);
  t.shininess = m.shininess;
  t.exponent = m.shininess >= 0.0f && m.shininess <= float(kMaxIntegerExponent) &&
                       m.shininess == std::floor(m.shininess)
                   ? int32_t(m.shininess)
                   : -1;
}

namespace {

// Step 2: the shading normal at p. A flat triangle's is n0; otherwise the corner normals are
// interpolated with barycentrics clamped to the triangle (the unprojected point is on it only
// up to depth rounding, and a point just outside must not extrapolate), then normalised, which
// also removes the clamped weights' sum.
inline vec3 shadingNormal(const ShadingTriangle& t, const vec3& p) {
  if (t.flat) return t.n0;
  const vec3 ep(p.x - t.a.x, p.y - t.a.y, p.z - t.a.z);
  const float v_plane = dot3(ep, t.gv), w_plane = dot3(ep, t.gw);
  float u = maxZero((1.0f - v_plane) - w_plane);
  const float v = maxZero(v_plane), w = maxZero(w_plane);
  if (!((u + v) + w > 0.0f)) u = 1.0f;
  const vec3 interpolated((u * t.n0.x + v * t.n1.x) + w * t.n2.x,
                          (u * t.n0.y + v * t.n1.y) + w * t.n2.y,
                          (u * t.n0.z + v * t.n1.z) + w * t.n2.z);
  const float length2 = dot3(interpolated, interpolated);
  if (!(length2 > 1e-20f)) return t.geometric;
  const float inv_length = 1.0f / std::sqrt(length2);
  return vec3(interpolated.x * inv_length, interpolated.y * inv_length,
              interpolated.z * inv_length);
}

// Step 5 for one light: its diffuse and specular term times its visibility `vis`, added to
// `color`.
inline void addShadingLight(const ShadingLight& light, const ShadingTriangle& t, float vis,
                            const vec3& p, const vec3& n, const vec3& view, vec3& color) {
  if (!(vis > 0.0f)) return;
  const vec3 to_light(light.center.x - p.x, light.center.y - p.y, light.center.z - p.z);
  const float distance2 = dot3(to_light, to_light);
  const float n_dot_to_light = dot3(n, to_light);
  // Facing away: neither diffuse nor specular.
  if (!(distance2 > 0.0f) || !(n_dot_to_light > 0.0f)) return;
  const float inv_distance = 1.0f / std::sqrt(distance2);
  const float diffuse = n_dot_to_light * inv_distance;
  vec3 reflected(t.albedo.x * diffuse, t.albedo.y * diffuse, t.albedo.z * diffuse);
  if (t.has_specular) {
    const vec3 h(to_light.x * inv_distance + view.x, to_light.y * inv_distance + view.y,
                 to_light.z * inv_distance + view.z);
    const float h_length2 = dot3(h, h);
    const float n_dot_h =
        h_length2 > 0.0f ? maxZero(dot3(n, h)) * (1.0f / std::sqrt(h_length2)) : 0.0f;
    const float power = specularPower(n_dot_h, t);
    reflected = vec3(reflected.x + t.specular.x * power, reflected.y + t.specular.y * power,
                     reflected.z + t.specular.z * power);
  }
  const float weight = vis < 1.0f ? vis : 1.0f;
  color = vec3(color.x + (reflected.x * light.radiance.x) * weight,
               color.y + (reflected.y * light.radiance.y) * weight,
               color.z + (reflected.z * light.radiance.z) * weight);
}

}  // namespace

void shadeRowScalar(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out) {
  const size_t row_pixel = size_t(y) * size_t(frame.width);
  const float* depth_row = frame.depth + row_pixel;
  const uint32_t* id_row = frame.primitive + row_pixel;
  const vec3 row_ray = frame.ray_origin + frame.ray_dy * (float(y) + 0.5f);
  ShadingTriangle scratch;
  for (int x = 0; x < frame.width; ++x) {
    const uint32_t id = id_row[x];
    const float depth = depth_row[x];
    // Depth is reversed-Z (core/view.h): > 0 wherever a triangle was drawn.
    if (id == kNoPrimitive || !(depth > 0.0f)) {
      out[x] = frame.background;
      continue;
    }
    // The pixel's triangle record (ShadingTriangleTable::get).
    const ShadingTriangle& t = triangles.get(id, scratch);
    // Step 1: the view ray and the visible point on it.
    const float fx = float(x) + 0.5f;
    const vec3 ray(row_ray.x + frame.ray_dx.x * fx, row_ray.y + frame.ray_dx.y * fx,
                   row_ray.z + frame.ray_dx.z * fx);
    const float scale = frame.near_plane / depth;
    const vec3 p(frame.eye.x + ray.x * scale, frame.eye.y + ray.y * scale,
                 frame.eye.z + ray.z * scale);
    vec3 n = shadingNormal(t, p);
    // Step 3: turn it to the side the eye sees, as the geometric normal decides (an interpolated
    // normal may lean away from the eye near a silhouette of a front face).
    if (dot3(t.geometric, ray) > 0.0f) n = -n;
    // Step 4: unit direction to the eye, for the half vector.
    vec3 view(0.0f);
    if (t.has_specular) {
      const float inv_ray = 1.0f / std::sqrt(dot3(ray, ray));
      view = vec3(-ray.x * inv_ray, -ray.y * inv_ray, -ray.z * inv_ray);
    }
    // Step 5: every light's diffuse and specular term times its visibility, onto ambient.
    vec3 color = t.ambient;
    for (const ShadingLight& light : frame.lights) {
      const float vis = light.visibility ? light.visibility[row_pixel + size_t(x)] : 1.0f;
      addShadingLight(light, t, vis, p, n, view, color);
    }
    out[x] = color;
  }
}

}  // namespace penumbra
