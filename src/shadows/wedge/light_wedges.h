#pragma once
// Everything the wedge passes draw for one light, in clip space: the umbra volume (front-plane
// quads of every unit silhouette edge, plus caps and skirts with z-fail) and the faces of every
// wedge polyhedron, each triangle tagged with what it contributes (WedgeRole).
#include <cstdint>
#include <vector>

#include "core/view.h"
#include "raster/depth_buffer.h"
#include "raster/triangle_setup.h"
#include "scene/scene.h"
#include "shadows/stages/caster_culling/caster_culling.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/wedge/wedge.h"
#include "shadows/wedge/wedge_screen.h"

namespace penumbra {

inline constexpr int32_t kNoWedge = -1;

struct WedgeRole {
  // Umbra: signed weight of a polygon facing out of the umbra volume (as shadow-volume
  // polygons: rasterizer.h), 0 when the triangle is not part of the umbra volume.
  int32_t umbra_weight = 0;
  // Penumbra: the wedge this triangle bounds, or kNoWedge; face_sign is +1 when the triangle
  // is wound to face out of that wedge, -1 when it is wound inward (an umbra quad with a
  // negative weight), so that "front-facing face of the wedge" is facing * face_sign > 0.
  int32_t wedge = kNoWedge;
  int8_t face_sign = 1;
  int8_t face = -1;     // which face of the wedge: a WedgeFace value, or -1
  bool zfail = false;   // the caster's volume is counted from infinity (z-fail)
};

// Faces of a wedge polyhedron, the region inside its four planes; kFar is its face at infinity
// when it is unbounded (light_wedges.cpp).
enum WedgeFace : int8_t { kFront = 0, kBack = 1, kLeft = 2, kRight = 3, kFar = 4 };

struct LightWedges {
  // Payload: index into roles. Finite caster vertices are the eye pass's (borrowed from the
  // EyeBuffers the wedges were built with, which must outlive it).
  ClipTriangles triangles;
  std::vector<WedgeRole> roles;
  std::vector<Wedge> wedges;       // all meshes' wedges; WedgeRole::wedge indexes these
  std::vector<ScreenWedge> screen; // same order
  uint64_t silhouette_edges = 0;
  uint64_t junction_vertices = 0;
  // Wedges left out of the penumbra passes because their four planes bound no proper convex
  // polyhedron (their umbra quads still count).
  uint64_t degenerate_wedges = 0;
};

// Builds the wedges of `light`. With a zero radius there are no wedge faces and the umbra
// volume is the hard shadow volume exactly (same clip vertices, same triangles), so every wedge
// variant then gives the hard-shadow image (resolved by the hard rule, li_buffer.h).
struct LightWedgesOptions {
  VolumeMode volume_mode = VolumeMode::Auto;  // ZPass for the 2002 algorithm
  bool smooth_falloff = false;
  // 0: every mesh's own silhouette. +1 or -1: only the triangles edge-on to the light centre
  // that the mesh does not already cast with this facing, cast with it (edge_on_sheet.h).
  int8_t edge_on_facing = 0;
  // Not null: only the meshes marked here (openMeshesWithBothFacings) cast, each with the facing
  // it otherwise leaves out (CasterPolicy::SolidWithHolesOtherFacing): the wedges' second pass
  // (wedge_technique.cpp), as ShadowStencilOptions::casting_meshes for the coverage technique.
  const std::vector<uint8_t>* other_facing_meshes = nullptr;
  // Not null: the meshes it culls (caster_culling.h) build no wedge and no umbra quad.
  const CasterCulling* caster_culling = nullptr;
};
LightWedges buildLightWedges(const LightWedgesOptions& options, const Scene& scene,
                           const Light& light, const View& view, const EyeBuffers& eye);

}  // namespace penumbra
