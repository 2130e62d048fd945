#pragma once
// When the window draws. On the 2-core machines the viewer is made for, every millisecond the
// window spends drawing (the panel rasterized by SDL's software renderer, the image handed to
// the X server) is taken from the frame worker's threads. So the window draws only when what
// it shows changed, never more often than a 60 Hz display refreshes, and, while the user is not
// interacting, only as often as keeps its drawing under a small share of one core: the slower
// a draw measured, the longer the interval, up to four draws a second. While the user drags or
// clicks, the window follows at the display's rate (the frames are previews then, and the hand
// waits for them).
#include <chrono>

namespace penumbra::viewer {

class PresentPacer {
 public:
  using Clock = std::chrono::steady_clock;
  using Ms = std::chrono::duration<double, std::milli>;

  static constexpr Ms kMinInterval{16.0};   // a 60 Hz display's refresh
  static constexpr Ms kMaxInterval{250.0};  // a refined frame waits at most this long
  // The first draws create the font texture and map the window: not what a draw costs.
  static constexpr int kWarmupDraws = 2;
  // The share of one core the window's drawing may take while nobody interacts.
  static constexpr double kIdleDrawShare = 0.04;

  // True when a draw may start at `now`.
  bool due(Clock::time_point now, bool interacting) const;
  // Milliseconds from `now` until due(now, interacting) turns true (0 when it is).
  double untilDue(Clock::time_point now, bool interacting) const;
  // A draw that started at `start` and took `took`: the next one is timed from it, and its
  // cost enters the running estimate.
  void drew(Clock::time_point start, Ms took);
  // The interval between draws while nobody interacts.
  Ms idleInterval() const;
  Ms drawCost() const { return cost_; }  // the running estimate

 private:
  Clock::time_point last_{};
  Ms cost_{0.0};
  int draws_ = 0;
};

}  // namespace penumbra::viewer
