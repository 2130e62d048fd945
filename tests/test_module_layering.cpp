// The library's layering, read off the include lines of the source tree (README, Architecture):
// modules include only modules listed before them (core, scene, raster, shadows, render,
// metrics, evaluation, then the apps), and a technique folder under src/shadows/ includes only
// its own files, the shared stages (src/shadows/stages/), the technique contract (the headers
// directly in shadows/) and lower modules, never another technique's folder. A stage never
// includes a technique folder. Only the technique table, which lists every technique, includes
// them all; the modules above shadows see only the contract and the options headers.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace penumbra::testing {
namespace test_module_layering {

namespace fs = std::filesystem;

const std::vector<std::string> kModuleOrder = {"core",    "scene",   "raster",     "shadows",
                                               "render",  "metrics", "evaluation", "apps"};

int moduleRank(const std::string& module) {
  const auto it = std::find(kModuleOrder.begin(), kModuleOrder.end(), module);
  return it == kModuleOrder.end() ? -1 : int(it - kModuleOrder.begin());
}

// A file of the tree by its path from the repository's root, and the paths it includes as
// written ("shadows/stages/stencil/shadow_stencil.h", "penumbra/core/image.h").
struct SourceFile {
  std::string path;
  std::vector<std::string> includes;
};

// The module of a repository path: src/<module>/..., include/penumbra/<module>/..., apps/...
std::optional<std::string> moduleOfFile(const std::string& path) {
  const fs::path p(path);
  std::vector<std::string> parts(p.begin(), p.end());
  if (parts.size() >= 3 && parts[0] == "src") return parts[1];
  if (parts.size() >= 4 && parts[0] == "include" && parts[1] == "penumbra") return parts[2];
  if (parts.size() >= 2 && parts[0] == "apps") return std::string("apps");
  return std::nullopt;
}

// The library path an include names ("shadows/exact/x.h"), with the installed prefix dropped.
std::string libraryPath(const std::string& include) {
  const std::string prefix = "penumbra/";
  return include.starts_with(prefix) ? include.substr(prefix.size()) : include;
}

// The folder right under src/shadows/ ("exact", "stages"), or "" for the contract's files
// directly in shadows/.
std::string shadowsFolder(const std::string& library_path) {
  const fs::path p(library_path);
  std::vector<std::string> parts(p.begin(), p.end());
  if (parts.size() >= 3 && parts[0] == "shadows") return parts[1];
  return "";
}

bool isTechniqueTable(const std::string& path) {
  return fs::path(path).filename().string().starts_with("technique_table.");
}

// Every include of `file` that breaks the layering, as "file includes X: why".
std::vector<std::string> layeringViolations(const SourceFile& file) {
  std::vector<std::string> out;
  const std::optional<std::string> module = moduleOfFile(file.path);
  if (!module) return out;
  const std::string own_folder =
      *module == "shadows" && file.path.starts_with("src/")
          ? shadowsFolder(file.path.substr(std::string("src/").size()))
          : "";
  for (const std::string& include : file.includes) {
    const std::string target = libraryPath(include);
    const std::optional<std::string> target_module = moduleOfFile("src/" + target);
    if (!target_module || moduleRank(*target_module) < 0) continue;  // a third-party header
    if (moduleRank(*target_module) > moduleRank(*module)) {
      out.push_back(file.path + " includes " + include + ": module " + *target_module +
                    " comes after " + *module);
      continue;
    }
    if (*target_module != "shadows") continue;
    const std::string target_folder = shadowsFolder(target);
    if (*module != "shadows") {
      // Above the shadows module, a technique is reached by its name through the contract.
      if (!target_folder.empty()) {
        out.push_back(file.path + " includes " + include + ": shadows/" + target_folder +
                      "/ is inside the shadows module; use the technique contract " +
                      "(shadows/technique.h) and the options headers");
      }
      continue;
    }
    if (target_folder.empty() || target_folder == "stages" || target_folder == own_folder) continue;
    if (own_folder.empty() && isTechniqueTable(file.path)) continue;
    out.push_back(file.path + " includes " + include + ": the technique folder shadows/" +
                  target_folder + "/ is a leaf, " +
                  (own_folder == "stages" ? std::string("and a stage must not depend on it")
                                          : "reached only through the technique table"));
  }
  return out;
}

std::vector<std::string> includesOf(const fs::path& path) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  std::vector<std::string> includes;
  std::ifstream in(path);
  std::string line;
  std::smatch match;
  while (std::getline(in, line)) {
    if (std::regex_search(line, match, kInclude)) includes.push_back(match[1]);
  }
  return includes;
}

std::vector<SourceFile> repositorySources() {
  const fs::path root(PENUMBRA_SOURCE_DIR);
  std::vector<SourceFile> files;
  for (const char* top : {"src", "include", "apps"}) {
    if (!fs::is_directory(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      files.push_back(
          {fs::relative(entry.path(), root).generic_string(), includesOf(entry.path())});
    }
  }
  return files;
}

// The tree as it is: a violation means a change made a technique depend on another technique's
// folder (so changing one silently changes the other) or a module on a later one.
TEST(ModuleLayering, NoIncludeRunsUpTheModuleOrderOrAcrossTechniqueFolders) {
  const std::vector<SourceFile> files = repositorySources();
  ASSERT_GT(files.size(), 100u) << "the source tree was not found under " << PENUMBRA_SOURCE_DIR;
  std::vector<std::string> violations;
  for (const SourceFile& file : files) {
    for (std::string& v : layeringViolations(file)) violations.push_back(std::move(v));
  }
  std::string message;
  for (const std::string& v : violations) message += "  " + v + "\n";
  EXPECT_TRUE(violations.empty()) << violations.size() << " layering violations:\n" << message;
}

// The checker itself catches each kind of violation: otherwise the test above passes on any tree.
TEST(ModuleLayering, ACrossTechniqueIncludeIsReported) {
  const auto v = layeringViolations(
      {"src/shadows/coverage/coverage_technique.cpp", {"shadows/exact/pixel_edges.h"}});
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("shadows/exact/ is a leaf"), std::string::npos) << v[0];
}

TEST(ModuleLayering, AStageIncludingATechniqueIsReported) {
  EXPECT_EQ(layeringViolations({"src/shadows/stages/stencil/shadow_stencil.cpp",
                                {"shadows/volume/volume_technique.h"}})
                .size(),
            1u);
}

TEST(ModuleLayering, AnUpwardIncludeIsReported) {
  EXPECT_EQ(layeringViolations({"src/scene/scene_file.cpp", {"render/frame.h"}}).size(), 1u);
  EXPECT_EQ(
      layeringViolations({"src/shadows/mask/mask_technique.cpp", {"render/shading.h"}}).size(), 1u);
  EXPECT_EQ(
      layeringViolations({"include/penumbra/core/stats.h", {"penumbra/scene/scene.h"}}).size(), 1u);
}

TEST(ModuleLayering, AModuleAboveShadowsReachingIntoATechniqueIsReported) {
  EXPECT_EQ(layeringViolations({"src/evaluation/sweep.cpp", {"shadows/wedge/wedge_culling.h"}})
                .size(),
            1u);
}

TEST(ModuleLayering, AllowedIncludesAreNotReported) {
  const SourceFile technique = {"src/shadows/coverage/coverage_technique.cpp",
                                {"shadows/coverage/coverage_table.h",
                                 "shadows/stages/potential_edges/edge_bins.h",
                                 "shadows/technique.h", "penumbra/scene/scene.h",
                                 "raster/tile_kernels.h", "core/parallel.h", "glm/glm.hpp"}};
  EXPECT_TRUE(layeringViolations(technique).empty());
  EXPECT_TRUE(layeringViolations({"src/shadows/technique_table.cpp",
                                  {"shadows/exact/exact_technique.h"}})
                  .empty());
  EXPECT_TRUE(layeringViolations({"apps/penumbra/main.cpp", {"evaluation/sweep.h"}}).empty());
  EXPECT_TRUE(layeringViolations(
                  {"src/render/frame.cpp", {"shadows/technique.h", "shadows/wedge_options.h"}})
                  .empty());
}

}  // namespace test_module_layering
}  // namespace penumbra::testing
