#include "scene/load_mesh.h"

#include <filesystem>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/error.h"
#include "scene/assimp_read.h"
#include "scene/load_checks.h"
#include "scene/normals.h"
#include "scene/weld.h"

namespace penumbra {

namespace {

mat4 toGlm(const aiMatrix4x4& m) {
  // assimp matrices are row-major (a1..a4 is the first row); glm is column-major.
  return mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4,
              m.c4, m.d4);
}

struct Gathered {
  Mesh mesh;
  std::vector<vec3> file_normals;  // per corner; (0,0,0) where the file had none or a bad one
  bool any_file_normal = false;
};

void gatherNode(const aiScene& scene, const aiNode& node, const mat4& parent, Gathered& out) {
  const mat4 transform = parent * toGlm(node.mTransformation);
  const mat3 normal_matrix = glm::transpose(glm::inverse(mat3(transform)));
  // A mirroring transform turns counter-clockwise triangles clockwise: swap two corners back.
  const bool mirrored = glm::determinant(mat3(transform)) < 0.0f;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[node.mMeshes[i]];
    // SortByPType leaves points and lines in meshes of their own; triangulated polygons also
    // carry aiPrimitiveType_NGONEncodingFlag, so test the triangle bit only.
    if ((m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const uint32_t base = uint32_t(out.mesh.positions.size());
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D& p = m.mVertices[v];
      out.mesh.positions.push_back(vec3(transform * vec4(p.x, p.y, p.z, 1.0f)));
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;
      const unsigned order[3] = {0, mirrored ? 2u : 1u, mirrored ? 1u : 2u};
      for (unsigned k : order) {
        const unsigned v = face.mIndices[k];
        out.mesh.indices.push_back(base + v);
        vec3 n(0.0f);
        if (m.HasNormals()) {
          const aiVector3D& fn = m.mNormals[v];
          n = normal_matrix * vec3(fn.x, fn.y, fn.z);
          const float length = glm::length(n);
          n = length > 0.0f && std::isfinite(length) ? n / length : vec3(0.0f);
          out.any_file_normal |= n != vec3(0.0f);
        }
        out.file_normals.push_back(n);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    gatherNode(scene, *node.mChildren[c], transform, out);
  }
}

}  // namespace

Mesh loadMesh(const std::string& path) {
  std::error_code ec;
  PENUMBRA_CHECK(std::filesystem::exists(path, ec), "{}: mesh file not found", path);
  PENUMBRA_CHECK(std::filesystem::is_regular_file(path, ec), "{}: not a regular file", path);

  Assimp::Importer importer;
  // No JoinIdenticalVertices: welding is ours (weld.h), exact on positions only, so seams that
  // split normals or texture coordinates still share their edges. The file's bytes are checked
  // against their own header before assimp reads them (assimp_read.h); what is well formed but
  // not read right (triangle strips) is refused next, against the declaration.
  const aiScene* scene = &readTriangulatedScene(importer, path);
  const PlyHeader ply = readPlyHeader(path);
  checkPlyDeclaration(path, ply);
  PENUMBRA_CHECK(scene->mRootNode != nullptr, "{}: the file holds no scene graph", path);

  Gathered gathered;
  gatherNode(*scene, *scene->mRootNode, mat4(1.0f), gathered);
  Mesh& mesh = gathered.mesh;
  mesh.name = std::filesystem::path(path).filename().string();
  mesh.file_counts.vertices = mesh.positions.size();
  mesh.file_counts.triangles = mesh.triangleCount();
  checkLoadedCounts(path, ply, countReferencedVertices(mesh), mesh.file_counts);
  PENUMBRA_CHECK(!mesh.indices.empty(), "{}: the file has no triangles", path);
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    const vec3& p = mesh.positions[mesh.indices[i]];
    PENUMBRA_CHECK(isFinite(p),
                   "{}: vertex {} (corner {} of triangle {}) has a non-finite coordinate "
                   "({}, {}, {})",
                   path, mesh.indices[i], i % 3, i / 3, p.x, p.y, p.z);
  }

  if (gathered.any_file_normal) mesh.corner_normals = gathered.file_normals;
  mesh.file_counts.degenerate_dropped = weldPositions(mesh);
  if (gathered.any_file_normal) {
    // Keep the file's normals, computing only the corners where it had none or a bad one
    // (some exports hold NaN or zero normals).
    std::vector<vec3> from_file = std::move(mesh.corner_normals);
    computeCornerNormals(mesh);
    for (size_t i = 0; i < from_file.size(); ++i) {
      if (from_file[i] != vec3(0.0f)) mesh.corner_normals[i] = from_file[i];
    }
  } else {
    computeCornerNormals(mesh);
  }
  PENUMBRA_CHECK(!mesh.indices.empty(), "{}: every triangle is degenerate (repeated vertices)",
                 path);
  return mesh;
}

}  // namespace penumbra
