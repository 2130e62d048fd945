// Saving on request and on quitting, and the benchmark loop: the parts of the viewer's run
// that need the full-size frame of the current view, waited for when it is not there yet.
#include <algorithm>
#include <chrono>
#include <iostream>

#include <SDL.h>
#include <fmt/format.h>

#include "saving.h"
#include "viewer_app.h"

namespace penumbra::viewer {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

const DeliveredFrame& ViewerApp::waitForFullFrame() {
  if (have_full_ && full_.generation == model_.generation) return full_;
  frames_->submit(makeRequest(false));
  requested_generation_ = model_.generation;
  requested_preview_ = false;
  for (;;) {
    frames_->waitForFrame(100);
    std::optional<DeliveredFrame> delivered = frames_->take();
    if (!delivered) continue;
    if (!delivered->error.empty()) throw Error(delivered->error);
    const bool wanted = !delivered->preview && delivered->generation == model_.generation;
    shown_ = *delivered;
    if (!delivered->preview) {
      full_ = std::move(*delivered);
      have_full_ = true;
    }
    if (wanted) return full_;
  }
}

void ViewerApp::saveScreenshotNow(const std::string& png, const std::string& exr) {
  const DeliveredFrame& frame = waitForFullFrame();
  writeFrameScreenshot(png, *frame.frame);
  if (!exr.empty()) writeVisibilityExr(exr, *frame.frame);
  message_ = "saved " + png;
  std::cout << "penumbra view: saved " << png << (exr.empty() ? "" : " and " + exr) << std::endl;
}

void ViewerApp::saveSceneNow(const std::string& path) {
  const std::string command = saveSceneFile(path, scene_, model_, base_scene_);
  message_ = "saved " + path;
  std::cout << "penumbra view: saved " << path << "; the same frame: " << command << std::endl;
}

void ViewerApp::saveOnQuit() {
  if (!args_.save_scene.empty()) saveSceneNow(args_.save_scene);
  if (!args_.screenshot.empty()) saveScreenshotNow(args_.screenshot, args_.visibility);
  if (!args_.window_screenshot.empty()) {
    waitForFullFrame();
    shown_ = full_;
    updateOracle();
    saveWindowNow(args_.window_screenshot);
  }
}

// Full-size frames back to back while the window loop runs (events, texture upload, panel):
// the worker renders the same view again and again, never waiting for the window, which shows
// the newest frame at most every kPresentInterval (as run() does). The frame interval is
// measured from the worker's finishing times, the figure to set against `penumbra render
// --frames N` (bench/viewer_overhead.sh); the window's drawing is timed too.
void ViewerApp::runBench() {
  constexpr size_t kWarmup = 3;  // as `penumbra render --frames`: the first frames fault in memory
  const size_t wanted = kWarmup + size_t(args_.bench_frames) + 1;
  std::vector<double> draws;
  frames_->submit(makeRequest(false));
  frames_->setRepeat(true);
  while (frames_->finishTimes().size() < wanted && !quit_) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) handleEvent(event);
    frames_->waitForFrame(int(kPresentInterval.count()));
    std::optional<DeliveredFrame> delivered = frames_->take();
    if (!delivered) continue;
    if (!delivered->error.empty()) throw Error(delivered->error);
    frame_ms_.push_back(float(delivered->render_ms));
    if (frame_ms_.size() > 120) frame_ms_.pop_front();
    shown_ = std::move(*delivered);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_present_ >= kPresentInterval) {
      drawWindow();
      last_present_ = now;
      draws.push_back(std::chrono::duration<double, std::milli>(
                          std::chrono::steady_clock::now() - now)
                          .count());
    }
  }
  const std::vector<double> finished = frames_->finishTimes();
  frames_->setRepeat(false);
  std::vector<double> intervals;
  for (size_t i = kWarmup + 1; i < finished.size(); ++i) {
    intervals.push_back(finished[i] - finished[i - 1]);
  }
  const double interval = median(intervals);
  std::cout << fmt::format(
                   "viewer loop: {} frames {}x{} {}: median frame interval {:.3f} ms ({:.2f} "
                   "frames/s); the window drawn {} times, median {:.3f} ms\n",
                   intervals.size(), model_.width, model_.height, techniqueConfig(model_).describe(),
                   interval, interval > 0 ? 1000.0 / interval : 0.0, draws.size(), median(draws))
            << std::flush;
}

}  // namespace penumbra::viewer
