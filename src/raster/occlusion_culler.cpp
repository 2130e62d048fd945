#include "raster/occlusion_culler.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <queue>
#include <utility>

#include "core/parallel.h"
#include "core/timer.h"
#include "raster/occlusion_counters.h"
#include "raster/occlusion_query.h"
#include "raster/occlusion_raster.h"

namespace penumbra {
namespace {

// Batches of newly found visible objects grow from this many triangles, doubling up to the
// maximum: early batches small, so the nearest occluders reach the buffer before the traversal
// goes much farther; later ones large, so a batch's setup and binning are spread over many
// triangles.
constexpr uint64_t kFirstBatchTriangles = 4096;
constexpr uint64_t kMaxBatchTriangles = 131072;

// Adaptive occluder selection (the thesis's publication P3 selects occluders by their
// benefit): an object visible or found visible is drawn into the occlusion buffer only when its
// screen rect holds at least this many pixels per triangle. A far object of small triangles
// costs as much to set up as a near one and hides almost nothing; it is still drawn by the eye
// pass.
constexpr double kOccluderPixelsPerTriangle = 16.0;

bool worthDrawing(const ScreenBox& box, uint32_t triangles) {
  if (box.kind == ScreenBox::Kind::Outside) return false;
  const double pixels = double(box.x1 - box.x0 + 1) * double(box.y1 - box.y0 + 1);
  return pixels >= kOccluderPixelsPerTriangle * double(triangles);
}

struct QueuedNode {
  double key;  // nearest depth of its box; larger is closer (reversed-Z)
  uint32_t node;
  ScreenBox box;
  bool operator<(const QueuedNode& o) const {
    return key < o.key || (key == o.key && node > o.node);
  }
};

QueuedNode queued(const ObjectHierarchy& h, uint32_t node, const View& view) {
  const ScreenBox box = projectBox(h.nodes[node].bounds, view);
  const double key = box.kind == ScreenBox::Kind::Crossing
                         ? std::numeric_limits<double>::infinity()
                         : box.nearest;
  return {key, node, box};
}

}  // namespace

OcclusionCuller::OcclusionCuller(const Scene& scene) : hierarchy_(buildObjectHierarchy(scene)) {
  was_visible_.assign(hierarchy_.clusters.size(), 0);
  visible_point_.assign(hierarchy_.clusters.size(), vec3(0.0f));
}

void OcclusionCuller::drawBatch(const std::vector<uint32_t>& clusters,
                                const std::vector<vec4>& clip_vertices, Stats& stats, bool simd) {
  if (clusters.empty()) return;
  ClipTriangles tris(clip_vertices);
  size_t count = 0;
  for (uint32_t c : clusters) count += hierarchy_.clusters[c].count;
  tris.indices.resize(count * 3);
  tris.payload.resize(count);
  size_t k = 0;
  for (uint32_t c : clusters) {
    const ObjectCluster& cluster = hierarchy_.clusters[c];
    for (uint32_t i = cluster.first; i < cluster.first + cluster.count; ++i, ++k) {
      const uint32_t t = hierarchy_.triangles[i];
      std::copy_n(&hierarchy_.vertex_indices[size_t(t) * 3], 3, &tris.indices[k * 3]);
      tris.payload[k] = int32_t(t);
    }
  }
  stats.count(kOcclusionOccluderTriangles, drawOccluders(tris, occlusion_, simd));
  stats.count(kOcclusionBatches, 1);
}

// Front-to-back over the hierarchy (a queue ordered by the nearest depth of the nodes' boxes):
// a node whose box is hidden behind what the occlusion buffer holds is dropped with its subtree;
// a leaf's object that is not hidden is kept and, when worth drawing, joins the batch being
// gathered, drawn into the buffer once it is big enough, so the objects behind it are tested
// against it (the thesis's front-to-back traversal with occlusion queries, section 3.1). The
// objects visible in the previous frame are kept and drawn first, untested, as occluders
// (visible point tracking's coherence). Returns every object
// not dropped, in no particular order.
std::vector<uint32_t> OcclusionCuller::traverse(const View& view,
                                                const std::vector<vec4>& clip_vertices,
                                                Stats& stats, bool simd) {
  const ObjectHierarchy& h = hierarchy_;
  std::vector<uint8_t> accepted(h.clusters.size(), 0);
  std::vector<uint32_t> batch, result;
  for (uint32_t c = 0; c < h.clusters.size(); ++c) {
    if (!was_visible_[c]) continue;
    const ScreenBox box = projectBox(h.clusters[c].bounds, view);
    if (box.kind == ScreenBox::Kind::Outside) continue;
    accepted[c] = 1;
    result.push_back(c);
    if (worthDrawing(box, h.clusters[c].count)) batch.push_back(c);
  }
  drawBatch(batch, clip_vertices, stats, simd);
  batch.clear();
  uint64_t batch_triangles = 0, batch_limit = kFirstBatchTriangles;
  uint64_t tested = 0, hidden = 0, tiles_read = 0;
  std::priority_queue<QueuedNode> queue;
  if (!h.nodes.empty()) queue.push(queued(h, 0, view));
  while (!queue.empty()) {
    const QueuedNode q = queue.top();
    queue.pop();
    if (q.box.kind == ScreenBox::Kind::Outside) continue;
    ++tested;
    if (boxHidden(q.box, occlusion_, tiles_read)) {
      ++hidden;
      continue;
    }
    const ObjectNode& node = h.nodes[q.node];
    if (!node.leaf()) {
      queue.push(queued(h, node.first, view));
      queue.push(queued(h, node.first + 1, view));
      continue;
    }
    const uint32_t c = node.first;
    if (accepted[c]) continue;
    accepted[c] = 1;
    result.push_back(c);
    if (!worthDrawing(q.box, h.clusters[c].count)) continue;
    batch.push_back(c);
    batch_triangles += h.clusters[c].count;
    if (batch_triangles >= batch_limit) {
      drawBatch(batch, clip_vertices, stats, simd);
      batch.clear();
      batch_triangles = 0;
      batch_limit = std::min(kMaxBatchTriangles, batch_limit * 2);
    }
  }
  // The last batch too: the re-test reads the whole buffer (in a small scene every object may
  // be in this one batch, the occluders with what they hide).
  drawBatch(batch, clip_vertices, stats, simd);
  stats.count(kOcclusionNodesTested, tested);
  stats.count(kOcclusionNodesHidden, hidden);
  stats.count(kOcclusionTilesRead, tiles_read);
  return result;
}

// Every object the traversal kept, queried again against the whole occlusion buffer (drawn
// before an object behind it was found, or drawn untested as last frame's visible object, it
// may be hidden now). The query's condition as in the thesis's conditional queries (section
// 3.1): the box is read only when the cached visible point is not seen.
std::vector<uint32_t> OcclusionCuller::retest(const View& view, std::vector<uint32_t> accepted,
                                              Stats& stats) {
  std::vector<uint8_t> keep(accepted.size(), 0), point_hit(accepted.size(), 0);
  std::vector<uint64_t> tiles(accepted.size(), 0);
  parallelFor((accepted.size() + 255) / 256, [&](size_t chunk) {
    const size_t end = std::min(accepted.size(), (chunk + 1) * 256);
    for (size_t i = chunk * 256; i < end; ++i) {
      const uint32_t c = accepted[i];
      if (was_visible_[c] && pointVisible(visible_point_[c], view, occlusion_)) {
        keep[i] = point_hit[i] = 1;
        continue;
      }
      const ScreenBox box = projectBox(hierarchy_.clusters[c].bounds, view);
      keep[i] = box.kind != ScreenBox::Kind::Outside && !boxHidden(box, occlusion_, tiles[i]);
    }
  });
  uint64_t hits = 0, tiles_read = 0, tested = 0, hidden = 0;
  std::vector<uint32_t> kept;
  for (size_t i = 0; i < accepted.size(); ++i) {
    hits += point_hit[i];
    tiles_read += tiles[i];
    tested += point_hit[i] ? 0 : 1;
    hidden += keep[i] ? 0 : 1;
    if (keep[i]) kept.push_back(accepted[i]);
  }
  stats.count(kOcclusionPointHits, hits);
  stats.count(kOcclusionNodesTested, tested);
  stats.count(kOcclusionNodesHidden, hidden);
  stats.count(kOcclusionTilesRead, tiles_read);
  return kept;
}

// The kept objects' triangles in increasing id order: marked, then gathered chunk by chunk.
void OcclusionCuller::emitTriangles(const std::vector<uint32_t>& clusters, ClipTriangles& out) {
  const ObjectHierarchy& h = hierarchy_;
  const size_t n = h.triangleCount();
  triangle_marks_.assign(n, 0);
  parallelFor(clusters.size(), [&](size_t i) {
    const ObjectCluster& c = h.clusters[clusters[i]];
    for (uint32_t k = c.first; k < c.first + c.count; ++k) triangle_marks_[h.triangles[k]] = 1;
  });
  constexpr size_t kChunk = 65536;
  const size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<size_t> offsets(chunks + 1, 0);
  parallelFor(chunks, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * kChunk);
    size_t count = 0;
    for (size_t t = chunk * kChunk; t < end; ++t) count += triangle_marks_[t];
    offsets[chunk + 1] = count;
  });
  for (size_t i = 0; i < chunks; ++i) offsets[i + 1] += offsets[i];
  const size_t first = out.payload.size();
  out.indices.resize(out.indices.size() + offsets.back() * 3);
  out.payload.resize(first + offsets.back());
  parallelFor(chunks, [&](size_t chunk) {
    const size_t end = std::min(n, (chunk + 1) * kChunk);
    size_t k = first + offsets[chunk];
    for (size_t t = chunk * kChunk; t < end; ++t) {
      if (!triangle_marks_[t]) continue;
      std::copy_n(&h.vertex_indices[t * 3], 3, &out.indices[k * 3]);
      out.payload[k++] = int32_t(t);
    }
  });
}

void OcclusionCuller::selectTriangles(const View& view, const std::vector<vec4>& clip_vertices,
                                      ClipTriangles& out, Stats& stats, bool simd) {
  std::lock_guard lock(mutex_);
  clearOcclusionBuffer(occlusion_, view.width, view.height);
  std::vector<uint32_t> candidates = traverse(view, clip_vertices, stats, simd);
  const std::vector<uint32_t> kept = retest(view, std::move(candidates), stats);
  const size_t before = out.size();
  emitTriangles(kept, out);
  stats.count(kOcclusionSceneTriangles, hierarchy_.triangleCount());
  stats.count(kOcclusionSubmittedTriangles, out.size() - before);
  stats.count(kOcclusionClusters, hierarchy_.clusters.size());
  stats.count(kOcclusionClustersCulled, hierarchy_.clusters.size() - kept.size());
}

void OcclusionCuller::track(const View& view, const DepthBuffer& depth,
                            const Image<uint32_t>& primitive) {
  std::lock_guard lock(mutex_);
  const ObjectHierarchy& h = hierarchy_;
  std::fill(was_visible_.begin(), was_visible_.end(), 0);
  first_pixel_.assign(h.clusters.size(), std::numeric_limits<uint32_t>::max());
  const int width = primitive.width(), height = primitive.height();
  // Per cluster, its first pixel in row-major order (the same whatever the thread count).
  parallelFor(size_t(height), [&](size_t y) {
    const uint32_t* row = primitive.row(int(y));
    uint32_t last = kNoPrimitive;
    for (int x = 0; x < width; ++x) {
      if (row[x] == kNoPrimitive || row[x] == last) continue;
      last = row[x];
      const uint32_t c = h.cluster_of[row[x]];
      const uint32_t pixel = uint32_t(y) * uint32_t(width) + uint32_t(x);
      std::atomic_ref<uint32_t> first(first_pixel_[c]);
      uint32_t seen = first.load(std::memory_order_relaxed);
      while (pixel < seen && !first.compare_exchange_weak(seen, pixel, std::memory_order_relaxed)) {
      }
    }
  });
  parallelFor(h.clusters.size(), [&](size_t c) {
    const uint32_t pixel = first_pixel_[c];
    if (pixel == std::numeric_limits<uint32_t>::max()) return;
    was_visible_[c] = 1;
    const int x = int(pixel % uint32_t(width)), y = int(pixel / uint32_t(width));
    visible_point_[c] = vec3(view.unproject(x, y, depth.depth.at(x, y)));
  });
}

}  // namespace penumbra
