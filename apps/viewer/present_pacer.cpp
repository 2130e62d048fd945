#include "present_pacer.h"

#include <algorithm>

namespace penumbra::viewer {

namespace {

// The weight of the newest draw in the running estimate: a few draws follow a change of load
// (another program on the cores) without one slow draw halving the rate.
constexpr double kNewestWeight = 0.25;

}  // namespace

PresentPacer::Ms PresentPacer::idleInterval() const {
  return std::clamp(Ms(cost_.count() / kIdleDrawShare), kMinInterval, kMaxInterval);
}

bool PresentPacer::due(Clock::time_point now, bool interacting) const {
  const Ms since = now - last_;
  return since >= (interacting ? kMinInterval : idleInterval());
}

double PresentPacer::untilDue(Clock::time_point now, bool interacting) const {
  const Ms since = now - last_;
  return std::max(0.0, ((interacting ? kMinInterval : idleInterval()) - since).count());
}

void PresentPacer::drew(Clock::time_point start, Ms took) {
  last_ = start;
  ++draws_;
  if (draws_ <= kWarmupDraws) return;
  const bool first = draws_ == kWarmupDraws + 1;
  cost_ = first ? took : Ms(cost_.count() + kNewestWeight * (took.count() - cost_.count()));
}

}  // namespace penumbra::viewer
