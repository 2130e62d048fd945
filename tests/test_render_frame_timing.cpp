// Warm-frame timing (render/frame_timing.h): what `penumbra render --frames N` prints.
#include <gtest/gtest.h>

#include <regex>

#include "cli_test_util.h"
#include "core/error.h"
#include "core/stats.h"
#include "render/frame_timing.h"
#include "scene/builtin_scenes.h"

namespace penumbra {
namespace test_render_frame_timing {

// N timed frames after the warm-up, every pass of the frame with a median, min <= median <= max;
// the result holds a complete frame. If this failed, the warm timings would count the wrong
// frames, drop passes, or leave the caller a half-rendered frame to write.
TEST(FrameTiming, TimesTheRequestedFramesAndEveryPass) {
  const Scene scene = builtinScene("spheres");
  FrameOptions options;
  options.width = 64;
  options.height = 48;
  options.technique = TechniqueConfig("wedge-3pass");
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  const FrameTimings t = timeFrames(renderer, 3, 2, frame);
  EXPECT_EQ(t.frame_ms.size(), 3u);
  EXPECT_EQ(t.warmup, 2);
  EXPECT_LE(t.minMs(), t.medianMs());
  EXPECT_LE(t.medianMs(), t.maxMs());
  std::vector<std::string> passes;
  // A pass is part of a frame: its median cannot exceed the slowest whole frame (a pass timed
  // twice, or a frame's time missing a pass, would break this).
  for (const auto& [name, ms] : t.pass_median_ms) {
    passes.push_back(name);
    EXPECT_LE(ms, t.maxMs()) << name;
  }
  EXPECT_EQ(passes, (std::vector<std::string>{"eye", "caster culling", "wedges", "setup", "umbra",
                                               "penumbra", "resolve", "shade"}));
  ASSERT_EQ(frame.lights.size(), scene.lights.size());
  EXPECT_EQ(frame.color.width(), 64);
  EXPECT_THROW(timeFrames(renderer, 0, 1, frame), Error);
  EXPECT_THROW(timeFrames(renderer, 1, -1, frame), Error);
}

TEST(FrameTiming, MedianOfEvenAndOddCounts) {
  EXPECT_EQ(medianOf({}), 0.0);
  EXPECT_EQ(medianOf({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(medianOf({4.0, 1.0, 3.0, 2.0}), 2.5);
}

// Passes that ran beside others (exact_technique.cpp: the edges and their binning beside the
// stencil) are marked concurrent and left out of the total, which is the wall time of the
// others. If this failed, the frame time would count the overlapped time twice.
TEST(FrameTiming, ConcurrentPassesAreListedButNotAddedToTheTotal) {
  Stats s;
  s.time_ms = {{"stencil", 3.0},
               {std::string("edges") + std::string(kConcurrentPass), 2.5},
               {kConcurrentWait, 0.5},
               {"shade", 1.0}};
  EXPECT_DOUBLE_EQ(s.totalMs(), 4.5);
  EXPECT_TRUE(isConcurrentPass("binning (concurrent)"));
  EXPECT_FALSE(isConcurrentPass("binning"));
  EXPECT_EQ(passTimeText("edges", 2.5, 1), "edges 2.5");
}

// The exact technique's real passes: none negative (no consumer, JSON, Python or the viewer,
// may see a pass that ran in negative time), the edge side marked concurrent, and the others
// adding up to no more than the light's wall time. If this failed, "overlap -1.70" would be
// back, or the concurrent passes would be counted twice.
TEST(FrameTiming, ExactTechniqueReportsNoNegativePass) {
  const Scene scene = builtinScene("spheres");
  FrameOptions options;
  options.width = 48;
  options.height = 32;
  options.technique = TechniqueConfig("exact");
  const FrameRenderer renderer(scene, options);
  FrameResult frame;
  const std::string line = frameTimingsLine(timeFrames(renderer, 2, 0, frame));
  EXPECT_FALSE(std::regex_search(line, std::regex("-[0-9]"))) << line;
  EXPECT_NE(line.find("edges (concurrent)"), std::string::npos) << line;
  bool concurrent = false;
  for (const auto& [name, ms] : frame.total.time_ms) {
    EXPECT_GE(ms, 0.0) << name;
    concurrent = concurrent || isConcurrentPass(name);
  }
  EXPECT_TRUE(concurrent);
}

using testing::CliRun;
class FrameTimingCli : public testing::CliTest {};

// The line users read: the frame count, the warm-up, min / median / max and per-pass medians,
// after the usual summary; the image of the last frame is written.
TEST_F(FrameTimingCli, RenderFramesPrintsWarmTimings) {
  const CliRun r = run("render spheres --width 64 --height 48 --frames 3 --warmup 1 -o '" +
                       path("s.png") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex line(
      R"(3 warm frames \(1 warm-up\): min [0-9.]+, median [0-9.]+, max [0-9.]+ ms; median per pass: eye [0-9.]+, .*shade [0-9.]+ ms)");
  EXPECT_TRUE(std::regex_search(r.out, line)) << r.out;
  EXPECT_TRUE(std::filesystem::exists(path("s.png")));
  EXPECT_NE(run("render spheres --frames 0 --quiet").exit_code, 0);
}

// Without --warmup, three untimed frames: the first frames fault in the memory their passes
// allocate on the worker threads, and one warm-up left the median of three timed frames on
// one of those (dragon-res2 `exact`: 148 against 116 ms).
TEST_F(FrameTimingCli, RenderFramesWarmsUpThreeFramesByDefault) {
  const CliRun r = run("render spheres --width 32 --height 24 --frames 1 -o '" +
                       path("s.png") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 warm frame (3 warm-up)"), std::string::npos) << r.out;
}

}  // namespace test_render_frame_timing
}  // namespace penumbra
