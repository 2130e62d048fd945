#pragma once
// The per-row shading kernel of render/shading.cpp: a SIMD version (Highway, 4 to 16 pixels per
// step, dispatched at run time) and a scalar twin that follows the same steps in the same
// floating-point order and gives bit-identical colours (tests check it; the build passes
// -ffp-contract=off, so neither twin fuses a multiply-add).
//
// Shading model (render/shading.h): for each light, (Lambert + Blinn-Phong) x visibility, plus
// ambient x albedo. The shading normal interpolates the corner normals with barycentrics clamped
// to the triangle and faces the eye (the geometric normal decides the side).
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace penumbra {

// One visible triangle with its material, in float world space, prepared so that a pixel costs
// dot products: barycentrics v = dot(p - a, gv), w = dot(p - a, gw), u = 1 - v - w (gv, gw are
// the rows of the inverse Gram matrix of the edges applied to the edges; zero for a degenerate
// triangle, which then shades with its first corner's normal). No member initialisers: a
// frame's table of them is allocated without touching memory (ShadingTriangleTable).
struct ShadingTriangle {
  vec3 a, gv, gw;
  vec3 n0, n1, n2;  // corner normals; the geometric normal when the mesh has none
  vec3 geometric;   // unit
  vec3 albedo, specular;
  vec3 ambient;     // scene ambient x albedo
  // Blinn-Phong exponent: an integer in [0, kMaxIntegerExponent] is raised by repeated squaring
  // (a few multiplications instead of std::pow's exp/log; within a few ulps of pow); any other
  // shininess (exponent -1) goes through std::pow.
  int32_t exponent;
  float shininess;
  bool has_specular;
  // All three corner normals equal (flat faces, meshes without normals): the shading normal is
  // n0 itself, with no barycentrics and no normalisation (floors cover most pixels).
  bool flat;
};

inline constexpr int kMaxIntegerExponent = 1024;

struct ShadingLight {
  vec3 center{0.0f};
  vec3 radiance{0.0f};                // colour x intensity
  const float* visibility = nullptr;  // full image, row-major; null: unshadowed
};

// What shading reads over the whole frame. The view ray through pixel (x, y) is
// (ray_origin + ray_dy (y + 0.5)) + ray_dx (x + 0.5), scaled so that the point at reversed-Z
// depth d is eye + ray (near_plane / d) (core/view.h).
struct ShadingFrame {
  std::vector<ShadingLight> lights;
  const float* depth = nullptr;       // eye pass, row-major
  const uint32_t* primitive = nullptr;
  int width = 0;
  vec3 eye{0.0f};
  float near_plane = 0.0f;
  vec3 ray_origin{0.0f}, ray_dx{0.0f}, ray_dy{0.0f};
  vec3 background{0.0f};
};

// The frame's triangle records, each built the first time a pixel shows its triangle by
// whichever worker gets there first: a record is a function of the id alone, so which worker
// builds it, and where it is stored, changes no result. Records are stored one after the other
// in the order they are first asked for, a slot per global triangle id saying where: memory is
// reserved for every triangle of the scene but touched only for the visible ones, and those
// are packed, so a first frame faults in the pages its visible triangles fill rather than one
// page per visible triangle of a dense mesh (records indexed by id, 120 bytes each, left most
// of a 4 KiB page unused).
class ShadingTriangleTable {
 public:
  explicit ShadingTriangleTable(const Scene& scene);
  // The record of triangle `id`; `scratch` receives it when another worker is building it at
  // this moment. Throws penumbra::Error for an id outside the scene.
  const ShadingTriangle& get(uint32_t id, ShadingTriangle& scratch) {
    if (id < count_) {
      const uint32_t slot = slots_[id].load(std::memory_order_acquire);
      if (slot >= kFirstRecord) return records_[slot - kFirstRecord];
    }
    return getSlow(id, scratch);
  }

 private:
  // A slot: kEmpty, kBuilding, or kFirstRecord + the record's place in records_.
  static constexpr uint32_t kEmpty = 0, kBuilding = 1, kFirstRecord = 2;
  const ShadingTriangle& getSlow(uint32_t id, ShadingTriangle& scratch);
  void build(uint32_t id, ShadingTriangle& t) const;

  const Scene& scene_;
  uint64_t count_;
  std::unique_ptr<std::atomic<uint32_t>[]> slots_;  // zero-initialised: kEmpty
  std::atomic<uint32_t> used_{0};                   // records built
  std::unique_ptr<ShadingTriangle[]> records_;      // the first used_ are built
};

// Shades row y into out[0, width): every pixel is written, background included.
void shadeRow(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out,
              bool simd);
void shadeRowScalar(const ShadingFrame& frame, int y, ShadingTriangleTable& triangles, vec3* out);

}  // namespace penumbra
