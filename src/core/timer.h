#pragma once
#include <chrono>
#include <string>

#include "core/stats.h"

namespace penumbra {

// Records the wall time of a scope as one named pass in Stats::time_ms.
class PassTimer {
 public:
  PassTimer(Stats& stats, std::string name)
      : stats_(stats), name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}
  ~PassTimer() {
    auto end = std::chrono::steady_clock::now();
    stats_.time_ms.emplace_back(name_,
                                std::chrono::duration<double, std::milli>(end - start_).count());
  }
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

 private:
  Stats& stats_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace penumbra
