#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/simd_dispatch.h"
#include "render/stats_json.h"

namespace penumbra {
namespace test_output_stats_json {

// A frame assembled by hand: the stats writer only reports what it is given.
struct FakeFrame {
  Scene scene;
  FrameOptions options;
  FrameResult result;
};

FakeFrame fakeFrame() {
  FakeFrame f;
  f.scene.name = "fake";
  Mesh mesh;
  mesh.positions = {vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)};
  mesh.indices = {0, 1, 2};
  f.scene.meshes.push_back(mesh);
  f.scene.materials.emplace_back();
  Light a;
  a.center = vec3(1, 2, 3);
  a.radius = 0.5f;
  f.scene.lights = {a, Light{}};
  f.options.technique = TechniqueConfig("volume");
  f.options.technique.set("volume-mode", "zfail");
  f.options.context.threads = 3;
  f.result.view.width = 4;
  f.result.view.height = 2;
  f.result.eye.primitive = Image<uint32_t>(4, 2, 0u);
  f.result.eye.primitive[0] = kNoPrimitive;
  f.result.eye_stats.pixels_rasterized = 8;
  f.result.eye_stats.time_ms = {{"eye", 1.5}};
  for (int i = 0; i < 2; ++i) {
    TechniqueResult light;
    light.visibility = Image<float>(4, 2, i == 0 ? 0.5f : 1.0f);
    light.visibility[0] = 1.0f;  // background pixel: not counted in the mean
    light.stats.stencil_writes = 100 + uint64_t(i);
    light.stats.silhouette_edges = 7;
    light.stats.time_ms = {{"silhouette", 0.25}, {"volumes", 2.0}};
    f.result.lights.push_back(light);
  }
  f.result.total.add(f.result.eye_stats);
  for (const auto& l : f.result.lights) f.result.total.add(l.stats);
  f.result.total.time_ms.emplace_back("shade", 0.75);
  return f;
}

// The JSON must carry every counter and pass under stable names: scripts plot from it.
TEST(OutputStatsJson, HoldsCountersPassesAndOptions) {
  const FakeFrame f = fakeFrame();
  const auto doc = nlohmann::json::parse(frameStatsJson(f.scene, f.options, f.result));
  EXPECT_EQ(doc["scene"], "fake");
  EXPECT_EQ(doc["width"], 4);
  EXPECT_EQ(doc["height"], 2);
  EXPECT_EQ(doc["triangles"], 1);
  EXPECT_EQ(doc["technique"]["name"], "volume");
  EXPECT_EQ(doc["technique"]["volume_mode"], "zfail");
  EXPECT_EQ(doc["threads"], 3);
  // What ran: true unless PENUMBRA_SIMD=off or a scalar-only build sends the kernels scalar.
  EXPECT_EQ(doc["simd"], simdKernelsAvailable());
  EXPECT_TRUE(doc["machine"]["cpu"].is_string());
  EXPECT_GT(doc["machine"]["cores"].get<int>(), 0);
  EXPECT_EQ(doc["eye_pass"]["pixels_rasterized"], 8);
  ASSERT_EQ(doc["lights"].size(), 2u);
  const auto& light1 = doc["lights"][1];
  EXPECT_EQ(light1["stats"]["stencil_writes"], 101);
  EXPECT_EQ(light1["stats"]["silhouette_edges"], 7);
  for (const char* key : {"pixels_rasterized", "z_reads", "stencil_writes", "tiles_tested",
                          "tiles_culled", "silhouette_edges", "wedges", "triangles"}) {
    EXPECT_TRUE(light1["stats"].contains(key)) << key;
  }
  ASSERT_EQ(light1["stats"]["time_ms"].size(), 2u);
  EXPECT_EQ(light1["stats"]["time_ms"][1]["pass"], "volumes");
  EXPECT_DOUBLE_EQ(light1["stats"]["time_ms"][1]["ms"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(light1["stats"]["total_ms"].get<double>(), 2.25);
  EXPECT_DOUBLE_EQ(doc["lights"][0]["mean_visibility"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(doc["lights"][0]["radius"].get<double>(), 0.5);
  EXPECT_EQ(doc["total"]["stencil_writes"], 201);
  EXPECT_DOUBLE_EQ(doc["total"]["total_ms"].get<double>(), 1.5 + 2.25 * 2 + 0.75);
}

TEST(OutputStatsJson, WritesFileAndNamesItOnError) {
  const FakeFrame f = fakeFrame();
  const auto dir = std::filesystem::path(::testing::TempDir()) /
                   fmt::format("penumbra_stats_json_{}", ::getpid());
  std::filesystem::remove_all(dir);
  const std::string path = (dir / "a" / "stats.json").string();
  writeStatsJson(path, f.scene, f.options, f.result);
  std::ifstream in(path);
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["scene"], "fake");
  // Writing "into" a regular file as if it were a folder must fail with the path named.
  try {
    writeStatsJson((std::filesystem::path(path) / "x.json").string(), f.scene, f.options,
                   f.result);
    FAIL() << "writing below a file did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("stats.json"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// The summary names the size, the technique and every pass that is not the eye's or a
// light's (shading), so a user sees where the time went.
TEST(OutputStatsJson, SummaryLine) {
  const FakeFrame f = fakeFrame();
  const std::string line = frameSummaryLine(f.scene, f.options, f.result);
  EXPECT_NE(line.find("fake 4x2"), std::string::npos) << line;
  EXPECT_NE(line.find("volume (zfail)"), std::string::npos) << line;
  EXPECT_NE(line.find("light 1 2.2 ms (silhouette 0.2, volumes 2.0)"), std::string::npos) << line;
  EXPECT_NE(line.find("shade 0.8 ms"), std::string::npos) << line;
  EXPECT_EQ(line.find("eye 1.5 ms, eye"), std::string::npos) << line;  // eye not repeated
  EXPECT_NE(line.find("stencil writes 201"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

// Every volume mode the command line takes reads back as itself (the stats JSON prints it),
// and a typo is an error, not a silent default.
TEST(OutputStatsJson, VolumeModeNames) {
  TechniqueConfig config("volume");
  for (const char* mode : {"auto", "zpass", "zfail"}) {
    config.set("volume-mode", mode);
    EXPECT_EQ(config.get("volume-mode"), mode);
  }
  EXPECT_THROW(config.set("volume-mode", "zmaybe"), Error);
}

}  // namespace test_output_stats_json
}  // namespace penumbra
