#pragma once
// Errors a caller can cause (bad files, bad settings) throw penumbra::Error with a message that
// names the input and what is wrong. Internal invariants use PENUMBRA_DCHECK (debug builds only).
#include <cassert>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace penumbra {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace penumbra

// Always-on check of something the caller can break: throws penumbra::Error.
#define PENUMBRA_CHECK(condition, ...)                                 \
  do {                                                                 \
    if (!(condition)) throw ::penumbra::Error(fmt::format(__VA_ARGS__)); \
  } while (0)

// Internal invariant: compiled out of release builds.
#define PENUMBRA_DCHECK(condition) assert(condition)
