// `penumbra bench` and the wedge options of `penumbra render`, as a user runs them. The CMake
// test environment sets PENUMBRA_CLI to the built binary; without it these skip.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_test_util.h"
#include "core/image_io.h"

namespace penumbra {
namespace test_sweep_cli {

namespace fs = std::filesystem;

using testing::slurp;

// run(...) returns the exit code; stdout and stderr of the last run are in out_ and err_.
class SweepCli : public testing::CliTest {
 protected:
  int run(const std::string& args) {
    const testing::CliRun r = CliTest::run(args);
    out_ = r.out;
    err_ = r.err;
    return r.exit_code;
  }
  std::string out_, err_;
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
  // Culling never changes a pixel, and neither does the two-level stencil (on by default).
  ASSERT_EQ(run(fmt::format("render columns --technique wedge-1pass --width 64 --height 48 "
                            "--cull full --tile-size 16 --one-level-stencil --quiet "
                            "--visibility '{}'",
                            path("one-level.exr"))),
            0)
      << err_;
  EXPECT_EQ(readExr(path("none.exr")), readExr(path("full.exr")));
  EXPECT_EQ(readExr(path("none.exr")), readExr(path("zmax.exr")));
  EXPECT_EQ(readExr(path("none.exr")), readExr(path("one-level.exr")));
  EXPECT_EQ(run("render columns --technique wedge-3pass --width 64 --height 48 --smooth --quiet"),
            0)
      << err_;
  EXPECT_EQ(run("render columns --technique wedge-3pass --tile-size 12 --quiet"), 1);
  EXPECT_NE(err_.find("--tile-size 12"), std::string::npos) << err_;
  EXPECT_EQ(run("render columns --technique wedge-3pass --tile-size 512 --quiet"), 1);
  EXPECT_EQ(run("render columns --technique wedge-3pass --cull sometimes --quiet"), 1);
}

}  // namespace test_sweep_cli
}  // namespace penumbra
