// `penumbra render --delay-stream BYTES` (raster/delay_stream.h): the same picture and
// visibility as without it, its counters in the stats JSON, bad sizes refused by name.
#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace penumbra {
namespace test_cli_delay_stream {

using testing::CliRun;
using testing::slurp;

class CliDelayStream : public testing::CliTest {};

TEST_F(CliDelayStream, SamePictureWithTheCountersInTheStats) {
  auto render = [&](const std::string& name, const std::string& extra) {
    const CliRun r = run(fmt::format(
        "render columns --width 96 --height 64 --technique volume -o '{}' --visibility '{}' "
        "--stats '{}' --quiet {}",
        path(name + ".png"), path(name + ".exr"), path(name + ".json"), extra));
    EXPECT_EQ(r.exit_code, 0) << r.err;
  };
  render("plain", "");
  render("delayed", "--delay-stream 65536");
  render("counted", "--depth-complexity");
  EXPECT_EQ(slurp(path("plain.png")), slurp(path("delayed.png")));
  EXPECT_EQ(slurp(path("plain.exr")), slurp(path("delayed.exr")));
  const auto plain = nlohmann::json::parse(slurp(path("plain.json")))["eye_pass"];
  const auto delayed = nlohmann::json::parse(slurp(path("delayed.json")))["eye_pass"];
  const auto counted = nlohmann::json::parse(slurp(path("counted.json")))["eye_pass"];
  EXPECT_FALSE(plain.contains("eye_depth_passes"));  // off: nothing new in the stats
  EXPECT_EQ(delayed["delay_ring_triangles"], 65536 / 52);
  EXPECT_TRUE(delayed.contains("delay_culled_pairs"));
  EXPECT_EQ(delayed["eye_covered_pixels"], counted["eye_covered_pixels"]);
  EXPECT_LE(delayed["eye_depth_passes"], counted["eye_depth_passes"]);
  EXPECT_LE(delayed["pixels_rasterized"], plain["pixels_rasterized"]);
  EXPECT_GT(counted["eye_covered_pixels"], 0);
}

TEST_F(CliDelayStream, BadSizesAreRefusedByName) {
  for (const char* bad : {"-1", "abc", "1e3", "99999999999999999999"}) {
    const CliRun r = run(fmt::format("render columns --width 16 --height 16 --quiet "
                                     "--delay-stream {}",
                                     bad));
    EXPECT_EQ(r.exit_code, 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--delay-stream"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace test_cli_delay_stream
}  // namespace penumbra
