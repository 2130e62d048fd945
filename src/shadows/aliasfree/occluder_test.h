#pragma once
// The alias-free shadow map's one question, asked of an occluder triangle and a batch of eye
// samples: does the segment from the light centre to the sample cross the triangle? It is the
// oracle's hard shadow ray (reference_technique.cpp) asked the other way round, from the
// triangle's side (Aila's 2005 thesis, section 4.1: the scene is rasterized from the light at
// the samples' exact light-space positions, which "exactly correspond to the intersections of
// shadow rays and the image plane of the light source").
//
// Everything is relative to the light centre L, in double: a sample is d = origin - L, where
// origin is the oracle's own float ray origin for the pixel (ray_origin.h). The triangle abc
// seen from L is three planes through L, one per edge, with normals N_ab = (a - L) x (b - L)
// etc.: d lies in the triangle's light-space image exactly when it is on the inner side of all
// three (this is the projected triangle's edge function, without projecting). It lies beyond
// the triangle when it is on the far side of the triangle's own plane from L.
//
// Tie rule: a sample exactly on an edge plane (value 0) belongs to the triangle whose inward
// edge normal has its first nonzero component positive. Two triangles sharing an edge compute
// that edge's normal from the same two float vertices in the other order, which gives the
// exact negation in floating point (products are the same, subtraction and negation commute),
// so a sample on the shared edge goes to exactly one of them when they face L the same way:
// no sample slips through the crack between them, as with a rasterizer's top-left rule.
//
// Values are evaluated in exactly the order written here, by the SIMD kernel and its scalar
// twin alike (no FMA: the build passes -ffp-contract=off), so both give the same bits:
//   edge value  = (N.x * d.x + N.y * d.y) + N.z * d.z
//   plane value = ((n.x * d.x + n.y * d.y) + n.z * d.z) - offset
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/math.h"

namespace penumbra {

struct OccluderTest {
  double edge[3][3];   // inward edge-plane normals through L: inside where the value is > 0
  bool edge_ties[3];   // true: a value of exactly 0 counts as inside (the tie rule above)
  double plane[3];     // the triangle's normal, turned away from L
  double offset;       // plane value at L is -offset < 0; behind the triangle where it is > 0
};

// The test for triangle abc and the light centre, or nothing when the triangle cannot shadow
// anything: degenerate, or exactly edge-on to L (a face edge-on to the light casts nothing, as
// in the shadow volumes and the oracle's intoSurface), or with a non-finite vertex.
std::optional<OccluderTest> makeOccluderTest(const vec3& a, const vec3& b, const vec3& c,
                                             const vec3& light);

// Samples per block: sample arrays hold a multiple of it and are aligned to
// kOccluderSampleAlignment bytes (8 doubles: one AVX-512 vector, two AVX2 ones).
inline constexpr size_t kOccluderBlock = 8;
inline constexpr size_t kOccluderSampleAlignment = 64;

// Sets shadowed[i] to -1 (all bits) for every sample i in [0, n) the triangle shadows; leaves
// the others as they are. dx, dy, dz: the samples relative to L. n is a multiple of
// kOccluderBlock.
void markShadowedSamples(const OccluderTest& test, const double* dx, const double* dy,
                         const double* dz, int64_t* shadowed, size_t n, bool simd);
void markShadowedSamplesScalar(const OccluderTest& test, const double* dx, const double* dy,
                               const double* dz, int64_t* shadowed, size_t n);

}  // namespace penumbra
