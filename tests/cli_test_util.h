#pragma once
// Running the built CLI from tests, as a user would: exit code, stdout and stderr. The CMake
// test environment sets PENUMBRA_CLI to the binary; without it (the test binary run by hand)
// these tests skip.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace penumbra::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fixture with a scratch folder of its own per test, the CLI run inside it.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* cli = std::getenv("PENUMBRA_CLI");
    if (!cli || !*cli) GTEST_SKIP() << "PENUMBRA_CLI is not set (run through ctest)";
    cli_ = cli;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(::testing::TempDir()) /
           fmt::format("penumbra_cli_{}_{}_{}", info->test_suite_name(), info->name(), ::getpid());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }

  // `env`: assignments put before the command, e.g. "PENUMBRA_SIMD=off".
  CliRun run(const std::string& args, const std::string& env = "") const {
    const std::filesystem::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = fmt::format("cd '{}' && {} '{}' {} >'{}' 2>'{}'", dir_.string(),
                                            env, cli_, args, out.string(), err.string());
    const int status = std::system(command.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string cli_;
  std::filesystem::path dir_;
};

}  // namespace penumbra::testing
