#include "shadows/stages/light_depth_maps/map_lookup_kernel.h"

namespace penumbra {

void pcfVisibilityScalar(const FaceTexels& face, const double* sx, const double* sy,
                         const double* receiver, const double* ring_bias, int kernel,
                         float* visibility, size_t n) {
  const int half_taps = (kernel - 1) / 2;
  const double half = 0.5 * (kernel - 1);
  for (size_t p = 0; p < n; ++p) {
    const int x0 = int(std::floor(sx[p] - half));
    const int y0 = int(std::floor(sy[p] - half));
    int lit = 0;
    for (int j = 0; j < kernel; ++j) {
      for (int i = 0; i < kernel; ++i) {
        const int ring = std::max(std::abs(i - half_taps), std::abs(j - half_taps));
        lit += occluderAt(face, x0 + i, y0 + j) >= receiver[p] - double(ring) * ring_bias[p];
      }
    }
    visibility[p] = float(lit) / float(kernel * kernel);
  }
}

}  // namespace penumbra
