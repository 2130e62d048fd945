// Saving on request and on quitting, and the benchmark loop: the parts of the viewer's run
// that need the full-size frame of the current view, waited for when it is not there yet.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include <SDL.h>
#include <fmt/format.h>

#include "saving.h"
#include "viewer_app.h"

namespace penumbra::viewer {

namespace {

// CPU milliseconds of this thread, or of the whole process, so far.
double cpuMs(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

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

// Full-size frames back to back while the window loop runs as run() runs it (events, the
// pacer, the frame texture, the panel): the worker renders the same view again and again,
// never waiting for the window. The frame interval is measured from the worker's finishing
// times, the figure to set against `penumbra render --frames N` (bench/viewer_overhead.sh);
// the window's draws are counted and timed too.
void ViewerApp::runBench() {
  constexpr size_t kWarmup = 3;  // as `penumbra render --frames`: the first frames fault in memory
  const size_t wanted = kWarmup + size_t(args_.bench_frames) + 1;
  std::vector<double> draws;
  frames_->submit(makeRequest(false));
  frames_->setRepeat(true);
  // CPU time, which a loaded machine does not inflate as it does wall time: the window's thread
  // against the whole process (the worker's threads rendering), from the end of the warm-up
  // frames (the window's first draws, which create its textures, are not counted either).
  double window_cpu_start = -1.0, process_cpu_start = 0.0;
  while (frames_->finishTimes().size() < wanted && !quit_) {
    if (window_cpu_start < 0.0 && frames_->finishTimes().size() > kWarmup) {
      window_cpu_start = cpuMs(CLOCK_THREAD_CPUTIME_ID);
      process_cpu_start = cpuMs(CLOCK_PROCESS_CPUTIME_ID);
      draws.clear();
    }
    input_this_frame_ = false;
    SDL_Event event;
    while (SDL_PollEvent(&event)) handleEvent(event);
    std::optional<DeliveredFrame> delivered = frames_->take();
    if (delivered) {
      if (!delivered->error.empty()) throw Error(delivered->error);
      frame_ms_.push_back(float(delivered->render_ms));
      if (frame_ms_.size() > 120) frame_ms_.pop_front();
      shown_ = std::move(*delivered);
    }
    const auto start = std::chrono::steady_clock::now();
    if (drawIfDue(input_this_frame_ || imgui_settle_ > 0)) {
      draws.push_back(std::chrono::duration<double, std::milli>(
                          std::chrono::steady_clock::now() - start)
                          .count());
    }
    waitForWork(input_this_frame_ || imgui_settle_ > 0);
  }
  if (window_cpu_start < 0.0) {
    window_cpu_start = cpuMs(CLOCK_THREAD_CPUTIME_ID);
    process_cpu_start = cpuMs(CLOCK_PROCESS_CPUTIME_ID);
  }
  const double window_cpu = cpuMs(CLOCK_THREAD_CPUTIME_ID) - window_cpu_start;
  const double process_cpu = cpuMs(CLOCK_PROCESS_CPUTIME_ID) - process_cpu_start;
  const std::vector<double> finished = frames_->finishTimes();
  frames_->setRepeat(false);
  std::vector<double> intervals;
  for (size_t i = kWarmup + 1; i < finished.size(); ++i) {
    intervals.push_back(finished[i] - finished[i - 1]);
  }
  const double interval = median(intervals);
  std::cout << fmt::format(
                   "viewer loop: {} frames {}x{} {}: median frame interval {:.3f} ms ({:.2f} "
                   "frames/s); the window drawn {} times, median {:.3f} ms; CPU: window thread "
                   "{:.1f} ms, rendering {:.1f} ms\n",
                   intervals.size(), model_.width, model_.height,
                   techniqueConfig(model_).describe(), interval,
                   interval > 0 ? 1000.0 / interval : 0.0, draws.size(), median(draws), window_cpu,
                   process_cpu - window_cpu)
            << std::flush;
}

}  // namespace penumbra::viewer
