#include "core/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

namespace penumbra {
namespace {

constexpr double kDefaultIntervalS = 0.1;  // ~10 redraws a second
constexpr const char* kEraseLine = "\r\x1b[K";  // carriage return, then erase to end of line

int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

int terminalColumns() {
  winsize size{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

void writeStderr(const std::string& text) {
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
}

}  // namespace

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  if (seconds < 10) return fmt::format("{:.1f}s", seconds);
  const auto s = static_cast<uint64_t>(seconds + 0.5);
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

std::string formatProgressLine(const std::string& label, uint64_t done, uint64_t total,
                               double elapsed_s, int columns) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, double(done) / double(total));
  const std::string eta = done >= total ? formatDuration(0.0)
                          : done > 0
                              ? formatDuration(elapsed_s * double(total - done) / double(done))
                              : formatDuration(-1.0);
  const std::string numbers =
      fmt::format("{:3.0f}%  {}/{}  {}, eta {}", std::floor(fraction * 100.0), done, total,
                  formatDuration(elapsed_s), eta);
  const std::string prefix = label.empty() ? std::string() : fmt::format("{} ", label);
  // Leave the last column free: writing into it makes some terminals wrap.
  const int room = columns - 1 - int(prefix.size()) - int(numbers.size()) - 2;
  constexpr int kMinBar = 10;
  constexpr int kMaxBar = 40;
  if (room < kMinBar + 2) {
    std::string line = fmt::format("{}{}", prefix, numbers);
    if (columns > 1 && int(line.size()) > columns - 1) line.resize(size_t(columns - 1));
    return line;
  }
  const int bar_width = std::min(kMaxBar, room - 2);
  const int filled = int(std::floor(fraction * bar_width));
  return fmt::format("{}[{}{}]  {}", prefix, std::string(size_t(filled), '#'),
                     std::string(size_t(bar_width - filled), '.'), numbers);
}

ProgressBar::ProgressBar(std::string label, uint64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      min_interval_ns_(int64_t(kDefaultIntervalS * 1e9)),
      start_ns_(nowNs()),
      last_draw_ns_(start_ns_) {
  if (enabled && isatty(STDERR_FILENO)) sink_ = writeStderr;
}

ProgressBar::ProgressBar(std::string label, uint64_t total, Sink sink, double min_interval_s)
    : label_(std::move(label)),
      total_(total),
      sink_(std::move(sink)),
      min_interval_ns_(int64_t(std::max(0.0, min_interval_s) * 1e9)),
      start_ns_(nowNs()),
      last_draw_ns_(start_ns_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::add(uint64_t n) {
  const uint64_t done_now = done_.fetch_add(n, std::memory_order_relaxed) + n;
  if (!sink_ || finished_.load(std::memory_order_relaxed)) return;
  const int64_t now = nowNs();
  int64_t last = last_draw_ns_.load(std::memory_order_relaxed);
  // The first draw waits one interval too, so work shorter than that never draws at all.
  if (now - last < min_interval_ns_) return;
  // Only the thread that moves the timestamp redraws; the others go back to work.
  if (!last_draw_ns_.compare_exchange_strong(last, now, std::memory_order_relaxed)) return;
  draw(done_now, now);
}

void ProgressBar::draw(uint64_t done_now, int64_t now_ns) {
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_.load(std::memory_order_relaxed)) return;
  const double elapsed_s = double(now_ns - start_ns_) * 1e-9;
  const int columns = sink_ && isatty(STDERR_FILENO) ? terminalColumns() : 80;
  sink_(kEraseLine + formatProgressLine(label_, done_now, total_, elapsed_s, columns));
  drew_ = true;
}

void ProgressBar::finish() {
  std::lock_guard lock(draw_mutex_);
  if (finished_.exchange(true)) return;
  if (sink_ && drew_) sink_(kEraseLine);
}

}  // namespace penumbra
