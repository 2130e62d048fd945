// Script parsing: a typo in a test's script must fail the test with its line, not be skipped.
#include <gtest/gtest.h>

#include <penumbra/core/error.h>

#include "input_script.h"

namespace penumbra::viewer {
namespace test_input_script {

TEST(InputScript, ReadsCommandsSkippingCommentsAndBlankLines) {
  const auto commands = parseScript(
      "# a comment\n\ndrag left 10 20 30 40 4 ctrl shift\n  technique volume  # switch\nwait 3\n",
      "t.txt");
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0].name, "drag");
  EXPECT_EQ(commands[0].line, 3);
  EXPECT_EQ(commands[0].args.size(), 8u);
  EXPECT_EQ(commands[1].name, "technique");
  EXPECT_EQ(commands[1].args, std::vector<std::string>{"volume"});
  EXPECT_EQ(commands[2].line, 5);
}

TEST(InputScript, UnknownCommandsAndWrongArgumentCountsNameTheLine) {
  try {
    parseScript("wait 1\nfly 3\n", "t.txt");
    FAIL() << "an unknown command was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("t.txt:2: unknown command 'fly'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parseScript("drag left 1 2\n", "t.txt"), Error);
  EXPECT_THROW(parseScript("wait\n", "t.txt"), Error);
  EXPECT_THROW(readScript("/no/such/script.txt"), Error);
}

}  // namespace test_input_script
}  // namespace penumbra::viewer
