#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "core/progress.h"

namespace penumbra {
namespace test_output_progress {

TEST(OutputProgress, FormatsLine) {
  const std::string line = formatProgressLine("rays", 250, 1000, 2.0, 100);
  EXPECT_NE(line.find("rays ["), std::string::npos) << line;
  EXPECT_NE(line.find(" 25%"), std::string::npos) << line;
  EXPECT_NE(line.find("250/1000"), std::string::npos) << line;
  EXPECT_NE(line.find("eta 6.0s"), std::string::npos) << line;  // 2 s per quarter
  EXPECT_LT(line.size(), 100u);
  // A narrow terminal drops the bar but keeps the numbers within the width.
  const std::string narrow = formatProgressLine("rays", 250, 1000, 2.0, 40);
  EXPECT_EQ(narrow.find('['), std::string::npos) << narrow;
  EXPECT_LE(narrow.size(), 39u);
}

TEST(OutputProgress, FormatsDurations) {
  EXPECT_EQ(formatDuration(0.42), "0.4s");
  EXPECT_EQ(formatDuration(12.4), "12s");
  EXPECT_EQ(formatDuration(185), "3m05s");
  EXPECT_EQ(formatDuration(3720), "1h02m");
  EXPECT_EQ(formatDuration(-1), "?");
}

// Concurrent increments must all count (an unsynchronised counter loses some), redraws happen
// when allowed, and finish() clears the line so the next output starts clean.
TEST(OutputProgress, CountsConcurrentlyAndClearsAtTheEnd) {
  std::vector<std::string> writes;
  {
    ProgressBar bar("work", 40000, [&](const std::string& s) { writes.push_back(s); }, 0.0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
      threads.emplace_back([&] {
        for (int i = 0; i < 10000; ++i) bar.add();
      });
    }
    for (auto& t : threads) t.join();
    EXPECT_EQ(bar.done(), 40000u);
    bar.finish();
    bar.finish();  // idempotent: no second clear
  }
  ASSERT_GE(writes.size(), 2u);
  EXPECT_NE(writes[writes.size() - 2].find("work ["), std::string::npos);
  EXPECT_EQ(writes.back(), "\r\x1b[K");
  for (size_t i = 0; i + 1 < writes.size(); ++i) EXPECT_NE(writes[i], "\r\x1b[K");
}

// Throttled: work shorter than the interval draws nothing at all, not even a clear.
TEST(OutputProgress, ShortWorkDrawsNothing) {
  std::vector<std::string> writes;
  {
    ProgressBar bar("quick", 10, [&](const std::string& s) { writes.push_back(s); }, 60.0);
    for (int i = 0; i < 10; ++i) bar.add();
  }
  EXPECT_TRUE(writes.empty());
}

// Not a terminal (the test's stderr is captured or a pipe under ctest) or disabled: silent.
TEST(OutputProgress, DisabledBarIsSilent) {
  ProgressBar bar("off", 5, false);
  EXPECT_FALSE(bar.drawing());
  bar.add(5);
  EXPECT_EQ(bar.done(), 5u);
}

}  // namespace test_output_progress
}  // namespace penumbra
