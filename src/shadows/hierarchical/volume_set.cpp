#include "shadows/hierarchical/volume_set.h"

#include <algorithm>
#include <array>

#include "core/parallel.h"
#include "core/timer.h"
#include "shadows/stages/caster_volumes/caster_volume.h"
#include "shadows/stages/silhouettes/silhouette_layer.h"

namespace penumbra {
namespace {

// The projected segment between two clip-space points (core/view.h conventions).
ScreenSegment screenSegment(const vec4& a, const vec4& b, const View& view) {
  ScreenSegment s{};
  const dvec4 p(a), q(b);
  if (!(p.w - p.z >= 0.0 && q.w - q.z >= 0.0 && p.w > 0.0 && q.w > 0.0)) {
    s.anywhere = true;
    return s;
  }
  s.x0 = (p.x / p.w * 0.5 + 0.5) * view.width;
  s.y0 = (0.5 - p.y / p.w * 0.5) * view.height;
  s.x1 = (q.x / q.w * 0.5 + 0.5) * view.width;
  s.y1 = (0.5 - q.y / q.w * 0.5) * view.height;
  s.anywhere = false;
  return s;
}

// One caster's shadow volume polygons, tagged with volume `tag` (owners[1]): the same polygons,
// in the same order and vertex order, as the per-pixel stencil's (shadow_stencil.cpp), so
// every pixel a volume polygon reaches gets bit-identical edge and depth values. A z-pass
// silhouette edge's quad keeps its segment (owners[0]), whose ends go to segment_ends.
void appendHierarchicalVolumePolygons(const Mesh& mesh, uint32_t tag, const vec3& centre,
                                      const View& view, CasterVolume& volume,
                                      ClipTriangles& polygons,
                                      std::vector<std::array<uint32_t, 2>>& segment_ends) {
  appendExtrudedVertices(mesh, centre, view, volume, polygons);
  const uint32_t finite = volume.finite, infinite = volume.infinite;
  const uint8_t flags = volume.zfail ? kZFail : 0;
  for (const SilhouetteEdge& e : volume.silhouette.edges) {
    uint32_t segment = ClipTriangles::kNoOwner;
    if (!volume.zfail) {
      segment = uint32_t(segment_ends.size());
      segment_ends.push_back({finite + e.v1, finite + e.v0});
    }
    polygons.addOwned(finite + e.v1, finite + e.v0, infinite + e.v0, e.multiplicity, flags,
                      segment, tag);
    polygons.addOwned(finite + e.v1, infinite + e.v0, infinite + e.v1, e.multiplicity, flags,
                      ClipTriangles::kNoOwner, tag);
  }
  // z-pass: caps are never in front of a visible point (volume_technique.cpp).
  if (volume.zfail)
    forEachCap(mesh, volume, [&](uint32_t a, uint32_t b, uint32_t c, int32_t weight) {
      polygons.addOwned(a, b, c, weight, flags, ClipTriangles::kNoOwner, tag);
    });
}

// The z-pass silhouette edges on screen (set.silhouettes), in parallel: each projection
// divides in double, and the edges' vertices lie anywhere in the eye pass's array (fractal's
// 10,306 segments took 0.3 ms in one thread).
void projectSilhouettes(const std::vector<std::array<uint32_t, 2>>& segment_ends,
                        const EyeBuffers& eye, const View& view, ShadowVolumeSet& set) {
  set.silhouettes.resize(segment_ends.size());
  constexpr size_t kSegmentChunk = 2048;
  parallelFor((segment_ends.size() + kSegmentChunk - 1) / kSegmentChunk, [&](size_t chunk) {
    const size_t end = std::min(segment_ends.size(), (chunk + 1) * kSegmentChunk);
    for (size_t i = chunk * kSegmentChunk; i < end; ++i)
      set.silhouettes[i] = screenSegment(eye.clip_vertices[segment_ends[i][0]],
                                         eye.clip_vertices[segment_ends[i][1]], view);
  });
}

// Each volume's run of set-up triangles (set-up keeps the input order) and its depth range,
// for the depth bounds test (thesis section 2.2).
void findVolumeRanges(size_t meshes, ShadowVolumeSet& set) {
  set.begin.assign(meshes + 1, 0);
  set.depth_min.assign(meshes, 1.0f);
  set.depth_max.assign(meshes, 0.0f);
  for (const SetupTriangle& t : set.triangles) {
    const uint32_t v = t.owners[1];
    ++set.begin[v + 1];
    set.depth_min[v] = std::min(set.depth_min[v], t.depth_min);
    set.depth_max[v] = std::max(set.depth_max[v], t.depth_max);
  }
  for (size_t m = 0; m < meshes; ++m) set.begin[m + 1] += set.begin[m];
}

}  // namespace

void indexVanishedPieces(const ClipTriangles& polygons, std::vector<VanishedPiece> pieces,
                         ShadowVolumeSet& set) {
  auto volumeOf = [&](const VanishedPiece& p) {
    return polygons.owners.empty() ? 0u : polygons.owners[2 * size_t(p.source) + 1];
  };
  // A counting sort by volume; set-up gives them in input order, so each volume's stay in it.
  set.vanished_begin.assign(set.volumeCount() + 1, 0);
  for (const VanishedPiece& p : pieces) ++set.vanished_begin[volumeOf(p) + 1];
  for (size_t v = 0; v < set.volumeCount(); ++v)
    set.vanished_begin[v + 1] += set.vanished_begin[v];
  set.vanished.resize(pieces.size());
  std::vector<uint32_t> next(set.vanished_begin.begin(), set.vanished_begin.end() - 1);
  for (const VanishedPiece& p : pieces) set.vanished[next[volumeOf(p)]++] = p;
}

ShadowVolumeSet buildShadowVolumes(const Scene& scene, const vec3& centre, const View& view,
                                   const EyeBuffers& eye, VolumeMode mode, Stats& stats,
                                   Image<float>* silhouette_layer,
                                   const CasterCulling* caster_culling) {
  PassTimer timer(stats, "silhouette");
  ShadowVolumeSet set;
  // Every mesh's polygons in one list, set up in one parallel pass (as the per-pixel stencil
  // does), each tagged with its volume in owners[1]; the volumes' ranges are then read off the
  // set-up triangles, which keep the input order.
  ClipTriangles polygons(eye.clip_vertices);
  const size_t meshes = scene.meshes.size();
  set.zfail.resize(meshes);
  set.may_contain_eye.resize(meshes);
  // Every caster's silhouette first, so that the polygon lists grow once.
  std::vector<CasterVolume> casters;
  casters.reserve(meshes);
  size_t triangle_room = 0, vertex_room = 0;
  std::vector<uint8_t> culled(meshes, 0);
  for (size_t m = 0; m < meshes; ++m) {
    if (caster_culling != nullptr && !caster_culling->mayShadow(m)) {
      culled[m] = 1;
      casters.emplace_back();
      continue;
    }
    casters.push_back(casterVolume(scene, m, eye, centre, view, mode, CasterPolicy::Auto));
    const CasterVolume& volume = casters.back();
    triangle_room += 2 * volume.silhouette.edges.size();
    if (volume.zfail) {
      for (const int8_t o : volume.silhouette.orientation) triangle_room += o != 0 ? 2 : 0;
    }
    vertex_room += scene.meshes[m].positions.size();
  }
  polygons.reserve(triangle_room, vertex_room);
  // The z-pass silhouette edges' ends (eye-pass vertices), projected after the loop.
  std::vector<std::array<uint32_t, 2>> segment_ends;
  for (size_t m = 0; m < meshes; ++m) {
    if (culled[m]) continue;  // zfail and may_contain_eye stay 0: no polygon reads them
    CasterVolume& volume = casters[m];
    stats.silhouette_edges += volume.silhouette.edges.size();
    if (silhouette_layer != nullptr)
      drawSilhouetteEdges(scene.meshes[m], volume.silhouette.edges, view, *silhouette_layer);
    appendHierarchicalVolumePolygons(scene.meshes[m], uint32_t(m), centre, view, volume,
                                     polygons, segment_ends);
    set.zfail[m] = volume.zfail;
    set.may_contain_eye[m] = mayContainNearPlane(view, centre, scene.meshes[m].bounds());
  }
  projectSilhouettes(segment_ends, eye, view, set);
  std::vector<VanishedPiece> vanished;
  set.triangles = setupTriangles(polygons, view.width, view.height, nullptr, &vanished);
  stats.triangles += set.triangles.size();
  indexVanishedPieces(polygons, std::move(vanished), set);
  findVolumeRanges(meshes, set);
  return set;
}

}  // namespace penumbra
