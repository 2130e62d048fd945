#pragma once
// Warm frames: a prepared FrameRenderer renders frame after frame into one FrameResult, as a
// viewer does, and the times are reduced to what people compare (min, median, max per frame,
// and the median of every pass). Timings are wall-clock and machine-dependent; counters are not.
#include <string>
#include <utility>
#include <vector>

#include "render/frame.h"

namespace penumbra {

struct FrameTimings {
  int warmup = 0;
  std::vector<double> frame_ms;  // each timed frame, in order
  // Per pass, in the order the passes ran, the median over the timed frames of the pass's time
  // in a frame (passes of the same name in one frame, one per light, summed).
  std::vector<std::pair<std::string, double>> pass_median_ms;
  double minMs() const;
  double medianMs() const;
  double maxMs() const;
};

// Renders `warmup` untimed frames, then `frames` timed ones, into `frame` (which ends holding
// the last). Throws penumbra::Error when frames < 1 or warmup < 0.
FrameTimings timeFrames(const FrameRenderer& renderer, int frames, int warmup, FrameResult& frame);

// "10 warm frames (1 warm-up): min 5.1, median 5.3, max 6.0 ms; median per pass: eye 0.6, ..."
std::string frameTimingsLine(const FrameTimings& timings);

// One pass of a pass list, "name 1.23" with `decimals` decimals. Passes that ran beside others
// carry their mark in the name ("edges (concurrent) 1.20"; Stats: kConcurrentPass), so a reader
// sees why they are not part of the total.
std::string passTimeText(const std::string& name, double ms, int decimals);

double medianOf(std::vector<double> values);  // 0 for none

}  // namespace penumbra
