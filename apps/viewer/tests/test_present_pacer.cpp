// The window's pacing (present_pacer.h): what would be wrong if these failed is a window that
// draws more often than it may (taking the renderer's cores) or one that stops following the
// user's hand.
#include <gtest/gtest.h>

#include "present_pacer.h"

namespace penumbra::viewer {
namespace test_present_pacer {

using Clock = PresentPacer::Clock;
using Ms = PresentPacer::Ms;

Clock::time_point at(double ms) {
  return Clock::time_point(std::chrono::duration_cast<Clock::duration>(Ms(ms)));
}

// The first draws (creating the font texture, mapping the window) do not count.
void warmUp(PresentPacer& pacer) {
  for (int i = 0; i < PresentPacer::kWarmupDraws; ++i) pacer.drew(at(0), Ms(400.0));
}

TEST(PresentPacer, NeverFasterThanTheDisplay) {
  PresentPacer pacer;
  warmUp(pacer);
  EXPECT_EQ(pacer.drawCost().count(), 0.0) << "a warm-up draw entered the estimate";
  pacer.drew(at(1000), Ms(0.1));  // a cheap draw
  EXPECT_FALSE(pacer.due(at(1010), true));
  EXPECT_TRUE(pacer.due(at(1016), true));
  EXPECT_TRUE(pacer.due(at(1016), false));
}

// A draw of 2 ms may take 4 % of a core while nobody interacts: one every 50 ms. While the
// user interacts, the display's rate.
TEST(PresentPacer, ExpensiveDrawsAreSpacedOutUnlessTheUserInteracts) {
  PresentPacer pacer;
  warmUp(pacer);
  pacer.drew(at(1000), Ms(2.0));
  EXPECT_NEAR(pacer.idleInterval().count(), 2.0 / PresentPacer::kIdleDrawShare, 1e-9);
  EXPECT_FALSE(pacer.due(at(1030), false));
  EXPECT_TRUE(pacer.due(at(1050), false));
  EXPECT_TRUE(pacer.due(at(1020), true));
  EXPECT_NEAR(pacer.untilDue(at(1030), false), 20.0, 1e-6);
  EXPECT_EQ(pacer.untilDue(at(1060), false), 0.0);
  // However slow the draws, a refined frame is shown within kMaxInterval.
  pacer.drew(at(2000), Ms(1000.0));
  EXPECT_TRUE(pacer.due(at(2000.0 + PresentPacer::kMaxInterval.count()), false));
}

// The cost is a running estimate: one slow draw moves it a quarter of the way.
TEST(PresentPacer, CostFollowsTheDrawsSmoothly) {
  PresentPacer pacer;
  warmUp(pacer);
  pacer.drew(at(0), Ms(1.0));
  EXPECT_EQ(pacer.drawCost().count(), 1.0);
  pacer.drew(at(100), Ms(5.0));
  EXPECT_NEAR(pacer.drawCost().count(), 2.0, 1e-9);
}

}  // namespace test_present_pacer
}  // namespace penumbra::viewer
