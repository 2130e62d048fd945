#pragma once
// Reading a mesh file through assimp without trusting it with hostile bytes: PLY and GLB
// containers are checked before assimp sees them (ply_check.h, glb_check.h), assimp's own
// validation runs before any post-processing, and polygons too large to triangulate in
// reasonable time are refused before triangulation.
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <string>

namespace penumbra {

// Ear clipping is quadratic in a polygon's corners: 300,000 corners take minutes. Real meshes'
// polygons have a handful.
constexpr unsigned kMaxPolygonCorners = 4096;

// The file at `path`, triangulated, with points and lines sorted into meshes of their own; owned
// by `importer`. Throws penumbra::Error naming the file and the problem.
const aiScene& readTriangulatedScene(Assimp::Importer& importer, const std::string& path);

}  // namespace penumbra
