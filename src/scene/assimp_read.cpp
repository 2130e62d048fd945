#include "scene/assimp_read.h"

#include <assimp/postprocess.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/path_extension.h"
#include "scene/glb_check.h"
#include "scene/ply_check.h"

namespace penumbra {
namespace {

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PENUMBRA_CHECK(in.good(), "{}: cannot open the mesh file", path);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  PENUMBRA_CHECK(!in.bad(), "{}: cannot read the mesh file", path);
  return std::move(bytes).str();
}

// Also sets each mesh's primitive types to exactly those its faces have: assimp's
// triangulation asserts (aborting the process) when a mesh claims polygons it does not hold,
// which a mutated PLY header produces and validation lets through.
void checkPolygonsAndTypes(aiScene& scene, const std::string& path) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned types = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const unsigned corners = mesh.mFaces[f].mNumIndices;
      PENUMBRA_CHECK(corners > 0, "{}: face {} of mesh {} has no corners", path, f, m);
      PENUMBRA_CHECK(corners <= kMaxPolygonCorners,
                     "{}: face {} of mesh {} has {} corners (the limit is {})", path, f, m, corners,
                     kMaxPolygonCorners);
      types |= corners == 1   ? aiPrimitiveType_POINT
               : corners == 2 ? aiPrimitiveType_LINE
               : corners == 3 ? aiPrimitiveType_TRIANGLE
                              : aiPrimitiveType_POLYGON;
    }
    mesh.mPrimitiveTypes = types;
  }
}

}  // namespace

const aiScene& readTriangulatedScene(Assimp::Importer& importer, const std::string& path) {
  // ValidateDataStructure runs first among the steps: it refuses faces with no indices or
  // indices past the vertex array (OFF or OBJ files that declare more than they hold), which
  // assimp's triangulation would otherwise assert on or read out of bounds.
  constexpr unsigned kReadFlags = aiProcess_ValidateDataStructure;
  const aiScene* scene = nullptr;
  const std::string ext = lowerExtension(path);
  if (ext == ".ply" || ext == ".glb") {
    // Self-contained formats: read once, check, and hand assimp exactly the checked bytes.
    const std::string bytes = readBytes(path);
    if (ext == ".ply") {
      checkPlyBytes(path, bytes);
    } else {
      checkGlbBytes(path, bytes);
    }
    scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), kReadFlags, ext.c_str() + 1);
  } else {
    // A text glTF names its buffers by path: assimp reads the file itself, after the check.
    if (ext == ".gltf") checkGltfText(path, readBytes(path));
    scene = importer.ReadFile(path, kReadFlags);
  }
  PENUMBRA_CHECK(scene != nullptr, "{}: cannot read mesh: {}", path, importer.GetErrorString());
  // The importer owns the scene; post-processing steps rewrite it in place the same way.
  checkPolygonsAndTypes(*const_cast<aiScene*>(scene), path);
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
  PENUMBRA_CHECK(scene != nullptr, "{}: cannot triangulate the mesh: {}", path,
                 importer.GetErrorString());
  return *scene;
}

}  // namespace penumbra
