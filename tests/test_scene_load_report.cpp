// What loading made of a mesh (scene/mesh_report.h) and the checks of a file against its own
// declaration (scene/load_checks.h, scene/ply_header.h): strip PLYs, lying headers, meshes that
// load far fewer triangles than their vertices suggest.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "scene/edges.h"
#include "scene/load_mesh.h"
#include "scene/mesh_report.h"
#include "scene/ply_header.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_load_report {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

std::string binaryPly(const std::string& elements, const std::string& body) {
  return "ply\nformat binary_little_endian 1.0\nelement vertex 6\nproperty float x\n"
         "property float y\nproperty float z\n" +
         elements + "end_header\n" + body;
}

template <typename T>
void append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// Six vertices of a strip of four triangles.
std::string stripVertices() {
  std::string bytes;
  const float xy[6][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}};
  for (const auto& v : xy) {
    append(bytes, v[0]);
    append(bytes, v[1]);
    append(bytes, 0.0f);
  }
  return bytes;
}

// igea.ply's layout in six vertices: assimp reads the strip as one triangle. If this failed,
// such a file would load silently as a single triangle (what the issue found).
TEST(LoadChecks, TriangleStripPlyIsAnErrorNamingTheFile) {
  ScratchDir dir;
  std::string body = stripVertices();
  append(body, int32_t(6));
  for (int32_t i = 0; i < 6; ++i) append(body, i);
  const std::string file = dir.write(
      "strips.ply", binaryPly("element tristrips 1\nproperty list int int vertex_indices\n", body));
  const std::string message = errorMessage([&] { loadMesh(file); });
  EXPECT_TRUE(contains(message, file) && contains(message, "triangle strips")) << message;
}

// An ASCII PLY that declares three faces and holds two: assimp makes up the third. If this
// failed, a cut-off or lying file would render with invented triangles. (The PLY check refuses it
// before assimp reads it: ply_check.h.)
TEST(LoadChecks, AsciiPlyHoldingFewerFacesThanDeclaredIsAnError) {
  ScratchDir dir;
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string file =
      dir.write("lying.ply", header + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
  const std::string message = errorMessage([&] { loadMesh(file); });
  EXPECT_TRUE(contains(message, file) && contains(message, "cut off")) << message;
  // The same file telling the truth loads, so the check is about the lie.
  const std::string honest = dir.write(
      "honest.ply", header.substr(0, header.find("face 3")) + "face 2" +
                        header.substr(header.find("face 3") + 6) +
                        "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
  EXPECT_EQ(loadMesh(honest).triangleCount(), 2u);
}

// A face of two corners would be kept by assimp as a line, so the declared faces would give
// fewer triangles. If this failed, faces would vanish from a file without a word. (The PLY
// check refuses it first; checkLoadedCounts stays as the net behind it.)
TEST(LoadChecks, PlyFacesLostInLoadingAreAnError) {
  ScratchDir dir;
  const std::string file = dir.write(
      "line.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n2 1 3\n");
  const std::string message = errorMessage([&] { loadMesh(file); });
  EXPECT_TRUE(contains(message, file) && contains(message, "face 1 has 2 vertex indices"))
      << message;
}

// Most vertices unused: the mesh loads, with a warning that says so. If this failed, a file
// whose surface mostly did not load would pass as a success.
TEST(LoadChecks, MostVerticesUnusedGivesAWarning) {
  ScratchDir dir;
  // PLY keeps the file's vertex list (assimp's OBJ reader keeps only the vertices faces use).
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 20\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 20; ++i) ply += std::to_string(i) + " 0 " + std::to_string(i % 3) + "\n";
  ply += "3 0 1 2\n";
  const Mesh mesh = loadMesh(dir.write("sparse.ply", ply));
  ASSERT_EQ(mesh.file_counts.warnings.size(), 1u);
  EXPECT_TRUE(contains(mesh.file_counts.warnings[0], "only 3 of the file's 20 vertices"))
      << mesh.file_counts.warnings[0];
  // A well-formed file gets none.
  const Mesh quad = loadMesh(dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_TRUE(quad.file_counts.warnings.empty());
}

TEST(PlyHeader, ReadsElements) {
  ScratchDir dir;
  const PlyHeader h = readPlyHeader(dir.write(
      "a.ply", "ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty float x\r\n"
               "element face 1\r\nend_header\r\n1\r\n2\r\n\r\n3 0 1 1\r\n"));
  ASSERT_TRUE(h.is_ply);
  ASSERT_EQ(h.elements.size(), 2u);
  EXPECT_EQ(h.elements[1].name, "face");
  EXPECT_EQ(h.elements[1].count, 1u);
  // No end_header, or not a PLY at all: not read as one (assimp reports those files).
  EXPECT_FALSE(readPlyHeader(dir.write("b.ply", "ply\nformat ascii 1.0\nelement vertex 2\n")).is_ply);
  EXPECT_FALSE(readPlyHeader(dir.write("c.obj", "v 0 0 0\n")).is_ply);
  EXPECT_FALSE(readPlyHeader(dir.write("d.ply", "ply\nelement vertex -2\nend_header\n")).is_ply);
}

// Every number of the report line on a file whose answers are known: two quads (one with
// split vertices that weld), a degenerate triangle, two components. If this failed, the line
// `render` prints would misstate the mesh.
TEST(MeshReport, CountsWhatTheLoaderDid) {
  ScratchDir dir;
  const std::string file = dir.write(
      "two.obj",
      // quad A as two triangles with its diagonal's vertices written twice
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 1 1 0\nv 0 1 0\nv 0 0 0\n"
      // quad B apart from it, and a triangle with a repeated position (degenerate after welding)
      "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nv 5 0 0\n"
      "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 7 9 10\nf 7 8 11\n");
  Mesh mesh = loadMesh(file);
  const EdgeAdjacency adjacency = buildEdges(mesh);
  const MeshReport r = reportMesh(mesh, adjacency);
  EXPECT_EQ(r.file_vertices, 15u);  // assimp gives OBJ files one vertex per face corner
  EXPECT_EQ(r.file_triangles, 5u);
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_EQ(r.welded_vertices, 8u);
  EXPECT_EQ(r.degenerate_dropped, 1u);
  EXPECT_EQ(r.open_edges, 8u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(meshReportLine(r),
            "two.obj: 4 triangles, 15 vertices read, 8 after welding, 8 open edges, 0 non-manifold "
            "edges, 1 degenerate triangles dropped, 2 components");
}

}  // namespace test_scene_load_report
}  // namespace penumbra
