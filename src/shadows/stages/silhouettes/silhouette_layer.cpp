#include "shadows/stages/silhouettes/silhouette_layer.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// Pixel coordinates of a clip-space point in front of the eye (w > 0), as View::unproject
// reads them back (y down).
dvec2 toPixels(const View& view, const dvec4& clip) {
  return {(clip.x / clip.w * 0.5 + 0.5) * view.width, (0.5 - clip.y / clip.w * 0.5) * view.height};
}

}  // namespace

void drawWorldSegment(const View& view, const vec3& a, const vec3& b, Image<float>& layer) {
  dvec4 ca = dvec4(view.toClip(vec4(a, 1.0f))), cb = dvec4(view.toClip(vec4(b, 1.0f)));
  // w is the view distance: keep the part at least the near plane away.
  const double near = double(view.near_plane);
  if (ca.w < near && cb.w < near) return;
  if (ca.w < near) ca = cb + (ca - cb) * ((cb.w - near) / (cb.w - ca.w));
  if (cb.w < near) cb = ca + (cb - ca) * ((ca.w - near) / (ca.w - cb.w));
  const dvec2 pa = toPixels(view, ca), pb = toPixels(view, cb);
  // One step per pixel along the longer axis, the line clipped to a margin around the image so
  // that an edge reaching far off screen does not take millions of steps.
  const double span = std::max(std::abs(pb.x - pa.x), std::abs(pb.y - pa.y));
  if (!std::isfinite(span)) return;  // a degenerate view: nothing to draw
  const double limit = 4.0 * double(std::max(view.width, view.height));
  const int steps = int(std::min(std::ceil(span), limit));
  for (int i = 0; i <= steps; ++i) {
    const double t = steps == 0 ? 0.0 : double(i) / steps;
    const double x = std::floor(pa.x + (pb.x - pa.x) * t);
    const double y = std::floor(pa.y + (pb.y - pa.y) * t);
    // Tested as doubles before converting: a point far off screen does not fit an int.
    if (!(x >= 0.0 && y >= 0.0 && x < layer.width() && y < layer.height())) continue;
    layer.at(int(x), int(y)) += 1.0f;
  }
}

void drawSilhouetteEdges(const Mesh& mesh, const std::vector<SilhouetteEdge>& edges,
                         const View& view, Image<float>& layer) {
  for (const SilhouetteEdge& edge : edges) {
    drawWorldSegment(view, mesh.positions[edge.v0], mesh.positions[edge.v1], layer);
  }
}

}  // namespace penumbra
