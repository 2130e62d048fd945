#pragma once
// The eye pass's counters of object-level occlusion culling (raster/occlusion_culler.h), reported
// with the eye pass's stats when culling is on.
#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kOcclusionSceneTriangles{
    "occlusion_scene_triangles", "occlusion culling: triangles in the scene"};
inline constexpr CounterSpec kOcclusionSubmittedTriangles{
    "occlusion_submitted_triangles",
    "occlusion culling: triangles submitted to the eye pass's rasterizer (of the scene's)"};
inline constexpr CounterSpec kOcclusionOccluderTriangles{
    "occlusion_occluder_triangles",
    "occlusion culling: triangles set up for the occlusion buffer (batches of visible objects)"};
inline constexpr CounterSpec kOcclusionClusters{
    "occlusion_clusters", "occlusion culling: objects (meshes and mesh clusters) in the scene"};
inline constexpr CounterSpec kOcclusionClustersCulled{
    "occlusion_clusters_culled",
    "occlusion culling: objects not submitted (hidden or off screen)"};
inline constexpr CounterSpec kOcclusionNodesTested{
    "occlusion_nodes_tested", "occlusion culling: hierarchy nodes and objects given the box query"};
inline constexpr CounterSpec kOcclusionNodesHidden{
    "occlusion_nodes_hidden", "occlusion culling: of those, the ones found hidden"};
inline constexpr CounterSpec kOcclusionPointHits{
    "occlusion_point_hits",
    "occlusion culling: objects shown visible by their cached visible point alone"};
inline constexpr CounterSpec kOcclusionTilesRead{
    "occlusion_tiles_read", "occlusion culling: tile z-min values read by the box queries"};
inline constexpr CounterSpec kOcclusionBatches{
    "occlusion_batches", "occlusion culling: batches drawn into the occlusion buffer"};

}  // namespace penumbra
