// Hostile mesh files, generated here: each must load correctly or end in a penumbra::Error that
// names the file and the problem, never a crash, an abort inside assimp, a hang or a silent
// wrong mesh. These are the crashes and hangs of issue 10's fuzzing list.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "scene/assimp_read.h"
#include "scene/load_mesh.h"
#include "scene/ply_check.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_scene_hostile_mesh_files {

using test::contains;
using test::errorMessage;
using test::ScratchDir;

std::string le32(uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[size_t(i)] = char((v >> (8 * i)) & 0xff);
  return s;
}
std::string f32(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return le32(u);
}

// A binary little-endian PLY of one triangle: 3 vertices (float x y z), 1 face (uchar count,
// int indices), with the header's face count and the indices given by the caller.
std::string binaryTriangle(const std::string& face_count, int i0, int i1, int i2,
                           bool truncate = false) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face " +
      face_count + "\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (float x : v) s += f32(x);
  s += char(3);
  s += le32(uint32_t(i0)) + le32(uint32_t(i1)) + le32(uint32_t(i2));
  if (truncate) s.resize(s.size() - 5);
  return s;
}

const char* kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

// The well-formed file both checks and loads: the checker does not refuse good input.
TEST(SceneHostileMeshFiles, GoodPlyFilesLoad) {
  ScratchDir dir;
  EXPECT_EQ(loadMesh(dir.write("a.ply", binaryTriangle("1", 0, 1, 2))).triangleCount(), 1u);
  EXPECT_EQ(
      loadMesh(dir.write("b.ply", std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
          .triangleCount(),
      1u);
}

// Negative and out-of-range face indices were read by loadMesh before any range check
// (segfault, heap overflow under ASan, coordinates from outside the vertex array).
TEST(SceneHostileMeshFiles, PlyIndicesOutOfRangeAreRefused) {
  ScratchDir dir;
  for (int bad : {-1, 3, 1000000, -2147483647}) {
    const std::string path = dir.write("bad.ply", binaryTriangle("1", 0, bad, 2));
    const std::string message = errorMessage([&] { loadMesh(path); });
    EXPECT_TRUE(contains(message, "bad.ply")) << message;
    EXPECT_TRUE(contains(message, "out of range")) << message;
  }
  const std::string ascii =
      dir.write("ascii.ply", std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 -5 2\n");
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(ascii); }), "out of range"));
}

// A binary body cut off, and a header that declares 1e6 faces over a body holding 1: assimp
// read past the buffer, or built a million coincident triangles.
TEST(SceneHostileMeshFiles, PlyBodyShorterThanDeclaredIsRefused) {
  ScratchDir dir;
  const std::string cut = dir.write("cut.ply", binaryTriangle("1", 0, 1, 2, true));
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(cut); }), "cut off"));
  const std::string lying = dir.write("lying.ply", binaryTriangle("1000000", 0, 1, 2));
  const std::string message = errorMessage([&] { loadMesh(lying); });
  EXPECT_TRUE(contains(message, "lying.ply: invalid PLY: the body is cut off")) << message;
  const std::string ascii = dir.write("ascii.ply", std::string(kAsciiHeader) + "0 0 0\n1 0 0\n");
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(ascii); }), "cut off"));
}

// A face with zero indices made assimp's triangulation assert (exit 134).
TEST(SceneHostileMeshFiles, PlyFaceWithFewerThanThreeIndicesIsRefused) {
  ScratchDir dir;
  const std::string path =
      dir.write("zero.ply", std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n0\n");
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(path); }), "face 0 has 0 vertex indices"));
}

// No end_header, or a header cut off: assimp spun at 100 % CPU forever.
TEST(SceneHostileMeshFiles, PlyHeaderWithoutEndIsRefused) {
  ScratchDir dir;
  const std::string full = binaryTriangle("1", 0, 1, 2);
  for (size_t cut : {size_t(4), size_t(30), full.find("end_header") + 3}) {
    const std::string path = dir.write("header.ply", full.substr(0, cut));
    const std::string message = errorMessage([&] { loadMesh(path); });
    EXPECT_TRUE(contains(message, "no end_header")) << cut << ": " << message;
  }
}

// A single-byte mutation at every position of a small binary PLY's header and body (the
// replacement byte cycling through NUL, line end, a digit and 0xff): a correct mesh or a
// penumbra::Error, never a signal (under ASan: never an out-of-bounds read). Assimp crashed
// or hung on mutated headers of a few hundred bytes.
TEST(SceneHostileMeshFiles, MutatedBinaryPlyNeverCrashes) {
  ScratchDir dir;
  const std::string good = binaryTriangle("1", 0, 1, 2);
  const std::string path = dir.path() + "/mutated.ply";
  int loaded = 0;
  int refused = 0;
  const char replacements[] = {'\0', '\n', '9', char(0xff)};
  for (size_t i = 0; i < good.size(); ++i) {
    for (char replacement : {replacements[i % 4], replacements[(i + 1) % 4]}) {
      if (good[i] == replacement) continue;
      std::string bytes = good;
      bytes[i] = replacement;
      dir.write("mutated.ply", bytes);
      try {
        const Mesh mesh = loadMesh(path);
        EXPECT_LE(mesh.triangleCount(), 1u);
        ++loaded;
      } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "mutated.ply")) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(loaded, 0);  // mutated coordinates still make a triangle
}

// An OFF file that declares more vertices than it holds made assimp's triangulation assert
// (exit 134); assimp's validation now refuses it first, or the mesh is what the file holds.
TEST(SceneHostileMeshFiles, OffDeclaringMoreVerticesThanItHolds) {
  ScratchDir dir;
  const std::string path = dir.write("short.off", "OFF\n8 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  try {
    const Mesh mesh = loadMesh(path);
    for (uint32_t index : mesh.indices) EXPECT_LT(index, mesh.positions.size());
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "short.off")) << e.what();
  }
}

// One OBJ face with 100,000-300,000 corners: triangulation ran for minutes. assimp's own
// validation refuses faces over 32767 corners; below that, ours refuses them by their corner
// count before triangulation, within a second.
TEST(SceneHostileMeshFiles, ObjFaceWithTooManyCornersIsRefusedQuickly) {
  ScratchDir dir;
  const int n = 20000;
  std::string text;
  text.reserve(size_t(n) * 24);
  for (int i = 0; i < n; ++i) text += fmt::format("v {} {} 0\n", i % 1000, i / 1000);
  text += "f";
  for (int i = 1; i <= n; ++i) text += fmt::format(" {}", i);
  text += "\n";
  const std::string path = dir.write("huge_face.obj", text);
  const auto start = std::chrono::steady_clock::now();
  const std::string message = errorMessage([&] { loadMesh(path); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(
      contains(message, "huge_face.obj: face 0 of mesh 0 has 20000 corners (the limit is 4096)"))
      << message;
  EXPECT_LT(seconds, 5.0);  // the quadratic triangulation took minutes
}

// A 12-byte GLB header plus a JSON chunk whose length says 2 GB: assimp allocated 2 GB. The
// length is checked against the file first.
TEST(SceneHostileMeshFiles, GlbChunkLongerThanTheFileIsRefused) {
  ScratchDir dir;
  const std::string json = R"({"asset":{"version":"2.0"}})";
  std::string glb =
      "glTF" + le32(2) + le32(uint32_t(12 + 8 + json.size())) + le32(0x80000000u) + "JSON" + json;
  const std::string path = dir.write("big.glb", glb);
  const std::string message = errorMessage([&] { loadMesh(path); });
  EXPECT_TRUE(contains(message, "big.glb: invalid GLB: chunk 0 says 2147483648 bytes")) << message;
  glb = "glTF" + le32(2) + le32(1u << 30) + le32(uint32_t(json.size())) + "JSON" + json;
  const std::string total = dir.write("total.glb", glb);
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(total); }), "the header says 1073741824 bytes"));
}

// The checker on its own: header lines it does not know are refused, not skipped.
TEST(SceneHostileMeshFiles, PlyCheckerRefusesUnknownHeaderLines) {
  const std::string text = "ply\nformat ascii 1.0\nelement vertex 0\nbogus line\nend_header\n";
  EXPECT_TRUE(contains(errorMessage([&] { checkPlyBytes("x.ply", text); }),
                       "x.ply: invalid PLY: header line 4: unknown keyword 'bogus'"));
  EXPECT_TRUE(contains(errorMessage([&] { checkPlyBytes("x.ply", "solid\n"); }),
                       "does not start with 'ply'"));
  EXPECT_NO_THROW(checkPlyBytes("x.ply", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n"));
}

// assimp 5.2 reads an unknown element's count from its name: a name starting with digits was
// an allocation of billions of items (a fuzzer's abort inside assimp), and an unknown element
// before the vertices would have its items read as vertices. Both refused, naming the element;
// an unknown element after the geometry (Stanford's range_grid) still loads.
TEST(SceneHostileMeshFiles, PlyElementsAssimpWouldMiscountAreRefused) {
  ScratchDir dir;
  const std::string digits =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement 6666666666666666face 1\nproperty list uchar int "
      "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string a = dir.write("digits.ply", digits);
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(a); }),
                       "digits.ply: invalid PLY: header line 7: element name "
                       "'6666666666666666face' starts with a digit"));
  const std::string before =
      "ply\nformat ascii 1.0\nelement extra 1\nproperty float w\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n9\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string b = dir.write("before.ply", before);
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(b); }),
                       "before.ply: invalid PLY: element 'extra' (1 items) comes before the "
                       "'vertex' element"));
  const std::string after = std::string(kAsciiHeader).insert(
                                std::string(kAsciiHeader).find("end_header"),
                                "element range_grid 1\nproperty list uchar int vertex_indices\n") +
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n1 0\n";
  EXPECT_EQ(loadMesh(dir.write("after.ply", after)).triangleCount(), 1u);
}

// A .gltf that is not a glTF: assimp 5.2 falls back to guessing the format from words in the
// bytes, and on this 24-byte file (a fuzzer's) one guess never returns. Refused before assimp,
// naming the JSON error; a JSON object without "asset" is refused too.
TEST(SceneHostileMeshFiles, GltfThatIsNotJsonIsRefusedBeforeAssimp) {
  ScratchDir dir;
  const std::string loop = dir.write("loop.gltf", std::string("glglTF{\xafxmgeometrynodels"));
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(loop); }), "loop.gltf: not a glTF file: invalid JSON"));
  const std::string bare = dir.write("bare.gltf", "{\"meshes\": []}");
  EXPECT_TRUE(contains(errorMessage([&] { loadMesh(bare); }),
                       "bare.gltf: not a glTF file: asset: missing"));
}

}  // namespace test_scene_hostile_mesh_files
}  // namespace penumbra
