// Scalar twin of occluder_kernel_simd.cpp: the same double operations in the same order
// (occluder_test.h).
#include "shadows/aliasfree/occluder_test.h"

namespace penumbra {
namespace {

bool insideEdge(const double* e, bool tie, double x, double y, double z) {
  const double v = (e[0] * x + e[1] * y) + e[2] * z;
  return v > 0.0 || (tie && v == 0.0);
}

}  // namespace

void markShadowedSamplesScalar(const OccluderTest& t, const double* dx, const double* dy,
                               const double* dz, int64_t* shadowed, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const double x = dx[i], y = dy[i], z = dz[i];
    const double behind = ((t.plane[0] * x + t.plane[1] * y) + t.plane[2] * z) - t.offset;
    if (insideEdge(t.edge[0], t.edge_ties[0], x, y, z) &&
        insideEdge(t.edge[1], t.edge_ties[1], x, y, z) &&
        insideEdge(t.edge[2], t.edge_ties[2], x, y, z) && behind > 0.0) {
      shadowed[i] = -1;
    }
  }
}

}  // namespace penumbra
