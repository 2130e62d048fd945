#include "cli_checks.h"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace penumbra::cli {

CLI::Validator wholeNumberIn(long long min, long long max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc::result_out_of_range) {
          return fmt::format("{} is not in {}..{}", text, min, max);
        }
        if (ec != std::errc() || stop != end)
          return fmt::format("'{}' is not a whole number", text);
        if (value < min || value > max) return fmt::format("{} is not in {}..{}", value, min, max);
        return std::string();
      },
      fmt::format("INT in {}..{}", min, max));
}

void checkDistinctOutputs(const std::vector<NamedOutput>& outputs) {
  namespace fs = std::filesystem;
  std::vector<fs::path> resolved;
  for (const NamedOutput& output : outputs) {
    std::error_code ec;
    fs::path path = fs::weakly_canonical(fs::absolute(output.path), ec);
    if (ec) path = fs::absolute(output.path).lexically_normal();
    resolved.push_back(path);
  }
  for (size_t i = 0; i < outputs.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      PENUMBRA_CHECK(resolved[i] != resolved[j],
                     "{} '{}' and {} '{}' are the same file: one would overwrite the other",
                     outputs[j].flag, outputs[j].path, outputs[i].flag, outputs[i].path);
    }
  }
}

}  // namespace penumbra::cli
