// penumbra scenes: the built-in scenes and the scene files of the source tree.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.h"
#include "scene/builtin_scenes.h"
#include "scene/model_sources.h"
#include "scene/scene_file.h"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

// "ready", "missing X: fetchable" or "optional, missing X: not on npm"; a scene file that
// cannot be read says why.
std::string sceneFileStatus(const std::string& path, const std::vector<std::string>& fetchable,
                            bool& any_fetchable, bool& any_optional) {
  std::vector<std::string> needed;
  try {
    needed = sceneFileModels(path);
  } catch (const std::exception& e) {
    return fmt::format("(cannot read: {})", e.what());
  }
  std::vector<std::string> missing;
  bool optional = false;
  for (const std::string& name : needed) {
    std::error_code ec;
    if (fs::exists(modelPath(name), ec)) continue;
    missing.push_back(name);
    optional |= std::find(fetchable.begin(), fetchable.end(), name) == fetchable.end();
  }
  if (missing.empty()) return "ready";
  any_optional |= optional;
  any_fetchable |= !optional;
  return fmt::format("{}missing {}{}", optional ? "optional, " : "", fmt::join(missing, ", "),
                     optional ? " (no npm package)" : " (scripts/fetch-models.sh)");
}

struct ScenesArgs {
  bool count = true;
};

int runScenes(const ScenesArgs& args) {
  std::cout << "built-in scenes:\n";
  for (const std::string& name : builtinSceneNames()) {
    if (!args.count) {
      std::cout << fmt::format("  {}\n", name);
      continue;
    }
    // Building a scene takes milliseconds; a failure is shown, not fatal, so the list stays
    // useful while one generator is broken.
    try {
      const Scene scene = builtinScene(name);
      std::cout << fmt::format("  {:<12} {:>8} triangles, {} light{}\n", name,
                               scene.triangleCount(), scene.lights.size(),
                               scene.lights.size() == 1 ? "" : "s");
    } catch (const std::exception& e) {
      std::cout << fmt::format("  {:<12} (cannot build: {})\n", name, e.what());
    }
  }
  // Not built here: the default city flattens to millions of triangles (seconds, gigabytes).
  for (const std::string& name : largeBuiltinSceneNames()) {
    std::cout << fmt::format("  {:<12} instanced, {}:N for the size N (docs/scene-format.md)\n",
                             name + "[:N]", name);
  }

  const fs::path root(PENUMBRA_SOURCE_DIR);
  std::vector<std::string> files;
  std::error_code ec;
  for (fs::directory_iterator it(root / "scenes", ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().extension() == ".json") {
      std::error_code relative_ec;
      const fs::path relative = fs::relative(it->path(), root, relative_ec);
      files.push_back((relative_ec ? it->path() : relative).string());
    }
  }
  std::sort(files.begin(), files.end());
  const std::string models = modelsDirectory();
  std::cout << fmt::format("scene files in {} (models from {}, then {}):\n", root.string(), models,
                           shippedModelsDirectory());
  if (files.empty()) std::cout << "  (none)\n";
  const std::vector<std::string> fetchable =
      fetchableModels((root / "scripts" / "models.tsv").string());
  bool any_fetchable = false;
  bool any_optional = false;
  for (const std::string& f : files) {
    std::cout << fmt::format("  {:<32} {}\n", f,
                             sceneFileStatus((root / f).string(), fetchable, any_fetchable,
                                             any_optional));
  }
  if (any_fetchable) {
    std::cout << "fetch the missing models from npm: scripts/fetch-models.sh (into "
              << (std::getenv("PENUMBRA_MODELS") ? models : userModelsCache()) << ")\n";
  }
  if (any_optional) {
    std::cout << "optional scene files need models no npm package ships: set PENUMBRA_MODELS "
                 "to a folder holding them\n";
  }
  return 0;
}

}  // namespace

Subcommand addScenesCommand(CLI::App& app) {
  auto args = std::make_shared<ScenesArgs>();
  CLI::App* cmd = app.add_subcommand("scenes", "List built-in scenes and scene files");
  cmd->add_flag("!--no-count", args->count, "Do not build the scenes to count triangles");
  return {cmd, [args] { return runScenes(*args); }};
}

}  // namespace penumbra::cli
