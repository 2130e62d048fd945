#pragma once
// A small progress bar for long work (the oracle's rays, big scenes). No progress-bar library is
// packaged in Debian 12, so this is our own.
//
// It draws on stderr only when stderr is a terminal: piped or logged output stays clean. Workers
// call add() concurrently (an atomic counter); at most one of them redraws, at most ~10 times a
// second, so the bar never slows the work it measures. finish() (or the destructor) clears the
// line, so what follows prints on a clean line.
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace penumbra {

class ProgressBar {
 public:
  // Receives the raw text a terminal would get (carriage returns and erase-line codes included).
  using Sink = std::function<void(const std::string&)>;

  // Draws on stderr when `enabled` and stderr is a terminal; otherwise counts silently.
  ProgressBar(std::string label, uint64_t total, bool enabled = true);
  // Draws into `sink` regardless of any terminal (for tests), at most once per `min_interval_s`.
  ProgressBar(std::string label, uint64_t total, Sink sink, double min_interval_s);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Thread-safe: counts `n` more items done and redraws if the last redraw is old enough.
  void add(uint64_t n = 1);
  // Clears the line if anything was drawn. Idempotent; later add() calls draw nothing.
  void finish();

  uint64_t done() const { return done_.load(std::memory_order_relaxed); }
  bool drawing() const { return static_cast<bool>(sink_); }

 private:
  void draw(uint64_t done_now, int64_t now_ns);

  std::string label_;
  uint64_t total_;
  Sink sink_;  // empty: silent
  int64_t min_interval_ns_;
  int64_t start_ns_;
  std::atomic<uint64_t> done_{0};
  std::atomic<int64_t> last_draw_ns_;
  std::atomic<bool> finished_{false};
  std::mutex draw_mutex_;  // one writer at a time; losers skip their redraw
  bool drew_ = false;      // guarded by draw_mutex_
};

// "label [#######.......]  45%  450/1000  1.2s, eta 1.5s" fitted into `columns` characters
// (the bar shrinks first, then disappears). Exposed for tests.
std::string formatProgressLine(const std::string& label, uint64_t done, uint64_t total,
                               double elapsed_s, int columns);
// Durations for people: "0.4s", "12s", "3m05s", "1h02m".
std::string formatDuration(double seconds);

}  // namespace penumbra
