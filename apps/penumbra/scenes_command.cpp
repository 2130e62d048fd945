// penumbra scenes: the built-in scenes and the scene files of the source tree.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "scene/builtin_scenes.h"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

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
  std::cout << fmt::format("scene files in {}:\n", root.string());
  if (files.empty()) std::cout << "  (none)\n";
  for (const std::string& f : files) std::cout << fmt::format("  {}\n", f);
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
