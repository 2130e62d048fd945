#pragma once
// The hot loop of `shadow-map`: percentage-closer filtering (Reeves, Salesin & Cook 1987) of a
// batch of points that land on one face of the light's depth maps, SIMD over the points (one
// lane per point, every lane the same N x N taps), with a scalar twin. Shared by `pcss`: the
// texel read (occluderAt) and the batch layout.
//
// Numeric conventions, kept by both twins (no FMA: the build passes -ffp-contract=off):
// positions and distances in double; the stored depth is reversed-Z float, near / distance, 0
// where nothing was drawn, read back as near / double(stored) (+infinity for 0); texel indices
// are int(floor(position)) clamped to the face, so lookups past the border read its edge
// texels (LightDepthMaps::occluder).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace penumbra {

// Batches hold a multiple of this many points (the widest double vector, AVX-512); the caller
// pads the tail with harmless points (padLookupBatch).
inline constexpr size_t kLookupBlock = 8;

// One face of the depth maps: size x size texels, row after row.
struct FaceTexels {
  const float* texels = nullptr;
  int size = 0;
  double near = 1.0;
};

// Distance of the occluder stored at texel (i, j), clamped to the face; +infinity where none.
inline double occluderAt(const FaceTexels& face, int i, int j) {
  const float stored = face.texels[size_t(std::clamp(j, 0, face.size - 1)) * size_t(face.size) +
                                   size_t(std::clamp(i, 0, face.size - 1))];
  return stored == 0.0f ? INFINITY : face.near / double(stored);
}

// Where a lookup position may lie, in texels, for the int conversion of its taps to stay in
// range: positions are clamped to [-2 size, 3 size] first. Every tap of a kernel at most `size`
// texels wide then reads the same clamped edge texel as it would from the unclamped position.
inline double clampLookupPosition(double s, int size) {
  return std::clamp(s, -2.0 * size, 3.0 * size);
}

// visibility[p] = the fraction of the kernel x kernel texels nearest (sx[p], sy[p]) (texel
// centres; x0 = floor(sx - (kernel - 1) / 2)) whose occluder is at or beyond
// receiver[p] - ring x ring_bias[p], where ring = max(|i - h|, |j - h|) for the tap (i, j) of
// the kernel, h = (kernel - 1) / 2: 0 for the centre tap, 1 for the eight around it, and so on.
// n is a multiple of kLookupBlock; kernel is odd, 1..15.
void pcfVisibility(const FaceTexels& face, const double* sx, const double* sy,
                   const double* receiver, const double* ring_bias, int kernel,
                   float* visibility, size_t n, bool simd);
void pcfVisibilityScalar(const FaceTexels& face, const double* sx, const double* sy,
                         const double* receiver, const double* ring_bias, int kernel,
                         float* visibility, size_t n);

}  // namespace penumbra
