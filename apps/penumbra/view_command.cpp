// penumbra view SCENE ...: runs the interactive viewer, penumbra-view (apps/viewer/), which
// is built beside this program when SDL2 and Dear ImGui were found at configure time.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "core/error.h"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

// penumbra-view beside this executable (the build folder, or the install's bin folder).
fs::path viewerPath() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return (ec ? fs::path(".") : self.parent_path()) / "penumbra-view";
}

int runView(const std::vector<std::string>& args) {
  const fs::path viewer = viewerPath();
  std::error_code ec;
  PENUMBRA_CHECK(fs::exists(viewer, ec),
                 "this build has no viewer ({} is missing): it was configured without SDL2 or "
                 "Dear ImGui. Install them (scripts/setup-debian.sh, or apt-get install "
                 "libsdl2-dev libimgui-dev) and configure and build again",
                 viewer.string());
  std::vector<std::string> words = {viewer.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execv(viewer.c_str(), argv.data());
  throw Error(fmt::format("cannot run {}: {}", viewer.string(), std::strerror(errno)));
}

}  // namespace

Subcommand addViewCommand(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "view", "Interactive viewer: penumbra view SCENE [--technique NAME] [options] "
              "(penumbra view --help lists them)");
  // Everything after `view` goes to penumbra-view as it is, --help included.
  cmd->prefix_command();
  cmd->set_help_flag();
  return {cmd, [cmd] { return runView(cmd->remaining()); }};
}

}  // namespace penumbra::cli
