#pragma once
// Checks of command-line values that CLI11 does not make, shared by the subcommands.
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::cli {

// A whole number in min..max: "--width 64abc" is "'64abc' is not a whole number", not
// CLI11's "not in range" (its Range validator reads the longest numeric prefix).
CLI::Validator wholeNumberIn(long long min, long long max);

// One output file named on the command line: the flag and the path.
struct NamedOutput {
  std::string flag;
  std::string path;
};

// Throws penumbra::Error when two outputs are the same file (after resolving '.', '..' and
// links): the later write would silently replace the earlier.
void checkDistinctOutputs(const std::vector<NamedOutput>& outputs);

}  // namespace penumbra::cli
