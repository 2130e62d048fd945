// Outputs on a full disk (/dev/full) or in a folder that cannot be made: an error naming the
// file and the reason, never exit code 0 with a 0-byte or truncated file, and no temporary file
// left behind. Before, EXR writes to a full disk exited 0 with 0-byte files and --stats left a
// 0-byte file with no reason given.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_util.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/output_file.h"

namespace penumbra {
namespace test_output_write_failures {

namespace fs = std::filesystem;

bool haveDevFull() { return fs::exists("/dev/full") && fs::is_character_file("/dev/full"); }

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// /dev/full accepts the open and refuses every write with ENOSPC, like a full disk.
TEST(OutputWriteFailures, FullDeviceIsAnErrorForEveryFormat) {
  if (!haveDevFull()) GTEST_SKIP() << "no /dev/full";
  const Image<float> gray(4, 3, 0.5f);
  const Image<vec3> color(4, 3, vec3(0.5f));
  for (const auto& [what, write] : std::vector<std::pair<std::string, std::function<void()>>>{
           {"EXR", [&] { writeExr("/dev/full", gray); }},
           {"PNG", [&] { writePng("/dev/full", color); }},
           {"PNG", [&] { writePngGray("/dev/full", gray); }},
           {"stats file", [&] { writeFileAtomically("/dev/full", "{}\n", "stats file"); }}}) {
    const std::string message = messageOf(write);
    EXPECT_NE(message.find("cannot write " + what + " '/dev/full'"), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));  // written in place, never replaced
}

// A target whose folder cannot be created (its parent is a file): an error, nothing written.
TEST(OutputWriteFailures, UncreatableFolderIsAnError) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("penumbra-write-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  const std::string target = (dir / "file" / "out.exr").string();
  const std::string message = messageOf([&] { writeExr(target, Image<float>(2, 2, 1.0f)); });
  EXPECT_NE(message.find("out.exr"), std::string::npos) << message;
  fs::remove_all(dir);
}

// A successful write replaces the target whole and leaves no temporary file beside it.
TEST(OutputWriteFailures, SuccessfulWriteLeavesOnlyTheTarget) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("penumbra-write-ok-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string target = (dir / "v.exr").string();
  std::ofstream(target) << "an older, longer file that must be replaced whole";
  writeExr(target, Image<float>(3, 2, 0.25f));
  const Image<float> back = readExr(target);
  EXPECT_EQ(back.width(), 3);
  EXPECT_EQ(back[0], 0.25f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

class OutputWriteFailuresCli : public testing::CliTest {};

// The CLI on a full disk: exit code 1 and the file named, for the render, the visibility and
// depth EXRs and the stats JSON.
TEST_F(OutputWriteFailuresCli, RenderToFullDiskFails) {
  if (!haveDevFull()) GTEST_SKIP() << "no /dev/full";
  // Links named as the options require (.png, .exr, .json), all to the full device.
  for (const char* name : {"full.png", "full.exr", "full.json"}) {
    fs::create_symlink("/dev/full", path(name));
  }
  const std::string base = "render spheres --width 16 --height 12 --quiet ";
  for (const auto& [args, file] : std::vector<std::pair<std::string, std::string>>{
           {base + "-o full.png", "full.png"},
           {base + "-o a.png --visibility full.exr", "full.exr"},
           {base + "-o a.png --depth full.exr", "full.exr"},
           {base + "-o a.png --stats full.json", "full.json"}}) {
    const testing::CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_NE(r.err.find("'" + file + "': No space left on device"), std::string::npos)
        << args << ": " << r.err;
  }
}

}  // namespace test_output_write_failures
}  // namespace penumbra
