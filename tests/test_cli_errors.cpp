// The CLI as a user runs it: exit codes and messages. The CMake test environment sets
// PENUMBRA_CLI to the built binary; without it (running the test binary by hand) these skip.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"

#include "core/image_io.h"

namespace penumbra {
namespace test_cli_errors {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::slurp;

class Cli : public testing::CliTest {};

void expectError(const CliRun& r, const std::string& mentions) {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
}

// A missing scene file: exit 1 with the file named, never a crash or an uncaught exception.
TEST_F(Cli, MissingSceneFileNamesIt) {
  expectError(run("render '" + path("no_such_scene.obj") + "' --quiet"), "no_such_scene.obj");
  expectError(run("render '" + path("no_such_scene.json") + "' --quiet"), "no_such_scene.json");
}

TEST_F(Cli, UnknownTechniqueIsAnError) {
  expectError(run("render spheres --technique bogus --quiet"), "bogus");
}

// An option the chosen technique does not have is refused with the technique's own options
// named, never silently ignored; and `render --technique NAME --help` and `techniques NAME`
// list that technique's options with their defaults.
TEST_F(Cli, TechniqueOptionsBelongToTheirTechnique) {
  const CliRun rays = run("render spheres --technique volume --rays 4 --quiet");
  expectError(rays, "--rays is not an option of technique 'volume'");
  EXPECT_NE(rays.err.find("--volume-mode"), std::string::npos) << rays.err;
  expectError(run("render spheres --technique reference --seed -1 --quiet"), "--seed");
  const CliRun help = run("render --technique reference --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--rays N"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("(default: 256)"), std::string::npos) << help.out;
  const CliRun listed = run("techniques wedge-1pass");
  EXPECT_EQ(listed.exit_code, 0);
  EXPECT_NE(listed.out.find("--tile-size N"), std::string::npos) << listed.out;
  EXPECT_EQ(listed.out.find("--umbra-tile-size"), std::string::npos) << listed.out;  // 3-pass only
  expectError(run("techniques bogus"), "bogus");
}

TEST_F(Cli, BadArgumentsAreErrors) {
  expectError(run(""), "subcommand");
  expectError(run("render spheres --rays 0 --quiet"), "rays");
  expectError(run("render spheres --technique volume --volume-mode sideways --quiet"), "sideways");
  expectError(run("render spheres -o picture.jpg --quiet"), "picture.jpg");
  expectError(run("frobnicate"), "frobnicate");
  EXPECT_EQ(run("--help").exit_code, 0);
  EXPECT_EQ(run("render --help").exit_code, 0);
}

TEST_F(Cli, CompareMissingFile) {
  Image<float> a(4, 4, 0.5f);
  writeExr(path("a.exr"), a);
  expectError(run("compare '" + path("a.exr") + "' '" + path("missing.exr") + "'"),
              "missing.exr");
}

TEST_F(Cli, CompareSizeMismatch) {
  writeExr(path("a.exr"), Image<float>(4, 4, 0.5f));
  writeExr(path("b.exr"), Image<float>(4, 5, 0.5f));
  expectError(run("compare '" + path("a.exr") + "' '" + path("b.exr") + "'"), "sizes differ");
}

TEST_F(Cli, CompareRejectsBadOptions) {
  writeExr(path("a.exr"), Image<float>(4, 4, 0.5f));
  const std::string a = "'" + path("a.exr") + "'";
  expectError(run("compare " + a + " " + a + " --tolerance -1"), "--tolerance");
  expectError(run("compare " + a + " " + a + " --diff x.png --diff-scale 0"), "--diff-scale");
  expectError(run("compare " + a + " " + a + " --diff x.jpg"), "x.jpg");
  expectError(run("compare " + a + " '" + path("a.txt") + "'"), "a.txt");
}

// compare reports the metrics (2 of 4 pixels off by 0.5: MAE 0.25) and writes the heat map.
TEST_F(Cli, CompareReportsMetricsAndWritesDiff) {
  Image<float> a(2, 2, 0.5f);
  Image<float> b = a;
  b[0] = 1.0f;
  b[3] = 0.0f;
  writeExr(path("a.exr"), a);
  writeExr(path("b.exr"), b);
  const CliRun text = run("compare '" + path("a.exr") + "' '" + path("b.exr") + "' --diff '" +
                          path("d/diff.png") + "'");
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("MAE 0.25"), std::string::npos) << text.out;
  EXPECT_TRUE(fs::exists(path("d/diff.png")));
  const Image<vec3> heat = readPng(path("d/diff.png"));
  EXPECT_EQ(heat.at(1, 0), vec3(0.0f));  // no error: black
  EXPECT_GT(heat.at(0, 0).x, 0.5f);      // the largest error: the brightest colour

  const CliRun json = run("compare '" + path("a.exr") + "' '" + path("b.exr") +
                          "' --json --tolerance 0.1");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_DOUBLE_EQ(doc["mae"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(doc["max_error"].get<double>(), 0.5);
  EXPECT_EQ(doc["count_over_tolerance"], 2);
  EXPECT_DOUBLE_EQ(doc["fraction_over_tolerance"].get<double>(), 0.5);
}

TEST_F(Cli, ScenesListsBuiltins) {
  const CliRun r = run("scenes --no-count");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("spheres"), std::string::npos) << r.out;
}

// End to end on a tiny frame: every requested output is written where asked, and the stats
// file describes the frame that was rendered.
TEST_F(Cli, RenderWritesRequestedOutputs) {
  const CliRun r = run(fmt::format(
      "render spheres --width 48 --height 32 -o '{}' --visibility '{}' --visibility-png '{}' "
      "--depth '{}' --stats '{}' --threads 2",
      path("o/img.png"), path("o/vis.exr"), path("o/vis.png"), path("o/depth.exr"),
      path("o/stats.json")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("48x32"), std::string::npos) << r.out;
  for (const char* f : {"o/img.png", "o/vis.exr", "o/vis.png", "o/depth.exr", "o/stats.json"}) {
    EXPECT_TRUE(fs::exists(path(f))) << f;
  }
  const Image<float> vis = readExr(path("o/vis.exr"));
  EXPECT_EQ(vis.width(), 48);
  EXPECT_EQ(vis.height(), 32);
  const auto stats = nlohmann::json::parse(slurp(path("o/stats.json")));
  EXPECT_EQ(stats["width"], 48);
  EXPECT_EQ(stats["threads"], 2);
  EXPECT_GE(stats["lights"].size(), 1u);
}

// Without -o the picture goes to out/<scene>.png under the working folder.
TEST_F(Cli, RenderDefaultOutput) {
  const CliRun r = run("render spheres --width 16 --height 16 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // --quiet prints nothing
  EXPECT_TRUE(fs::exists(path("out/spheres.png")));
}

}  // namespace test_cli_errors
}  // namespace penumbra
