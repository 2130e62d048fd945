// `penumbra bench` and the wedge options of `penumbra render`, as a user runs them. The CMake
// test environment sets PENUMBRA_CLI to the built binary; without it these skip.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "render/image_io.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class SweepCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* cli = std::getenv("PENUMBRA_CLI");
    if (!cli || !*cli) GTEST_SKIP() << "PENUMBRA_CLI is not set (run through ctest)";
    cli_ = cli;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           fmt::format("penumbra_sweep_cli_{}_{}", info->name(), ::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // Exit code; stdout and stderr into out_ and err_.
  int run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = fmt::format("cd '{}' && '{}' {} >'{}' 2>'{}'", dir_.string(), cli_,
                                            args, out.string(), err.string());
    const int status = std::system(command.c_str());
    out_ = slurp(out);
    err_ = slurp(err);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string cli_, out_, err_;
  fs::path dir_;
};

TEST_F(SweepCli, BenchWritesCsvAndSummary) {
  ASSERT_EQ(run("bench --scenes columns --width 64 --height 48 --repeat 1 --tile-levels 3,5 "
                "--oracle-rays 0 --no-plots --quiet --out sweep"),
            0)
      << err_;
  const std::string csv = slurp(path("sweep/sweep.csv"));
  size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, 1u + 2u * 3u * 2u + 1u) << csv;  // header, configurations, wedge-2002
  EXPECT_NE(slurp(path("sweep/summary.md")).find("Culling changed no pixel"), std::string::npos);
}

TEST_F(SweepCli, BenchRejectsBadOptions) {
  EXPECT_EQ(run("bench --scenes columns --tile-levels 9 --quiet"), 1);
  EXPECT_EQ(run("bench --scenes columns --cull sometimes --quiet --no-plots"), 1);
  EXPECT_NE(err_.find("sometimes"), std::string::npos) << err_;
  EXPECT_EQ(run("bench --scenes columns --techniques volume --quiet --no-plots"), 1);
}

TEST_F(SweepCli, RenderTakesCullingOptions) {
  for (const char* cull : {"none", "zmax", "full"}) {
    ASSERT_EQ(run(fmt::format("render columns --technique wedge-1pass --width 64 --height 48 "
                              "--cull {} --tile-size 16 --quiet --visibility '{}'",
                              cull, path(std::string(cull) + ".exr"))),
              0)
        << err_;
  }
  // Culling never changes a pixel.
  EXPECT_EQ(readExr(path("none.exr")), readExr(path("full.exr")));
  EXPECT_EQ(readExr(path("none.exr")), readExr(path("zmax.exr")));
  EXPECT_EQ(run("render columns --technique wedge-3pass --width 64 --height 48 --smooth --quiet"),
            0)
      << err_;
  EXPECT_EQ(run("render columns --technique wedge-3pass --tile-size 12 --quiet"), 1);
  EXPECT_NE(err_.find("--tile-size 12"), std::string::npos) << err_;
  EXPECT_EQ(run("render columns --technique wedge-3pass --tile-size 512 --quiet"), 1);
  EXPECT_EQ(run("render columns --technique wedge-3pass --cull sometimes --quiet"), 1);
}

}  // namespace
}  // namespace penumbra
