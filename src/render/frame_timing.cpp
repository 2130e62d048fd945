#include "render/frame_timing.h"

#include <algorithm>
#include <chrono>
#include <map>

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra {

double medianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double FrameTimings::minMs() const {
  return frame_ms.empty() ? 0.0 : *std::min_element(frame_ms.begin(), frame_ms.end());
}
double FrameTimings::medianMs() const { return medianOf(frame_ms); }
double FrameTimings::maxMs() const {
  return frame_ms.empty() ? 0.0 : *std::max_element(frame_ms.begin(), frame_ms.end());
}

FrameTimings timeFrames(const FrameRenderer& renderer, int frames, int warmup, FrameResult& frame) {
  PENUMBRA_CHECK(frames >= 1, "frames to time is {} but must be at least 1", frames);
  PENUMBRA_CHECK(warmup >= 0, "warm-up frames is {} but must be at least 0", warmup);
  FrameTimings t;
  t.warmup = warmup;
  for (int i = 0; i < warmup; ++i) renderer.render(frame);
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> runs;
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(frame);
    t.frame_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    std::map<std::string, double> in_frame;
    for (const auto& [name, ms] : frame.total.time_ms) {
      if (!runs.count(name) && !in_frame.count(name)) order.push_back(name);
      in_frame[name] += ms;
    }
    for (const auto& [name, ms] : in_frame) runs[name].push_back(ms);
  }
  for (const std::string& name : order) t.pass_median_ms.emplace_back(name, medianOf(runs[name]));
  return t;
}

std::string passTimeText(const std::string& name, double ms, int decimals) {
  return fmt::format("{} {:.{}f}", name, ms, decimals);
}

std::string frameTimingsLine(const FrameTimings& t) {
  std::string line = fmt::format(
      "{} warm frame{} ({} warm-up): min {:.2f}, median {:.2f}, max {:.2f} ms", t.frame_ms.size(),
      t.frame_ms.size() == 1 ? "" : "s", t.warmup, t.minMs(), t.medianMs(), t.maxMs());
  const char* separator = "; median per pass: ";
  for (const auto& [name, ms] : t.pass_median_ms) {
    line += separator + passTimeText(name, ms, 2);
    separator = ", ";
  }
  return line + " ms";
}

}  // namespace penumbra
