#pragma once
// Renders frames on a background thread so the window never waits for a slow technique: the
// window submits what it wants (the newest request replaces one not yet started) and takes
// finished frames when they arrive.
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <penumbra/penumbra.h>

namespace penumbra::viewer {

struct FrameRequest {
  uint64_t generation = 0;  // ViewerModel::generation when it was made
  Camera camera;
  std::vector<Light> lights;
  TechniqueConfig technique;
  RenderContext context;
  int width = 0, height = 0;  // the size to render at (a preview's is smaller)
  bool preview = false;       // rendered smaller, or with fewer samples, while the user drags
  std::vector<std::string> preview_options;  // "samples 16": options the preview lowered
};

struct DeliveredFrame {
  uint64_t generation = 0;
  // Counts the worker's frames from 1: what the window shows is keyed by it (a recycled
  // FrameResult keeps its address with new pixels).
  uint64_t sequence = 0;
  bool preview = false;
  std::vector<std::string> preview_options;  // as the request's
  std::shared_ptr<const FrameResult> frame;  // null when rendering failed
  std::string error;                         // why it failed
  double render_ms = 0;                      // FrameRenderer::render, wall clock
  double prepare_ms = 0;                     // > 0 when the technique was prepared for it
};

class FrameWorker {
 public:
  // The worker renders its own copy of `scene`: the window may change its copy meanwhile.
  explicit FrameWorker(Scene scene);
  ~FrameWorker();
  FrameWorker(const FrameWorker&) = delete;
  FrameWorker& operator=(const FrameWorker&) = delete;

  void submit(FrameRequest request);
  // The newest frame finished since the last call, if any.
  std::optional<DeliveredFrame> take();
  // Waits up to `milliseconds` for a frame to finish (the window's loop sleeps here rather than
  // spin while the worker renders).
  void waitForFrame(int milliseconds);
  // True while a request is pending or being rendered.
  bool busy() const;
  // Benchmarking: with `repeat`, the worker renders the last request again and again, never
  // waiting for the window to take a frame, and records when each frame finished.
  void setRepeat(bool repeat);
  // Finishing times of the frames rendered since setRepeat(true), in milliseconds from then.
  std::vector<double> finishTimes() const;

 private:
  void run();
  DeliveredFrame render(const FrameRequest& request);
  FrameRenderer& preparedRenderer(const FrameRequest& request, DeliveredFrame& delivered);
  std::shared_ptr<FrameResult> recycledFrame();

  Scene scene_;
  // The renderers prepared last, newest first, each with what it was prepared with
  // (preparedKey): a preview with fewer samples and the full frame after it each keep theirs.
  std::vector<std::pair<std::string, std::unique_ptr<FrameRenderer>>> renderers_;
  std::vector<std::shared_ptr<FrameResult>> pool_;  // frames handed out, reused when returned
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable delivered_;
  std::optional<FrameRequest> pending_;
  std::optional<DeliveredFrame> finished_;
  bool rendering_ = false;
  bool stop_ = false;
  bool repeat_ = false;
  std::optional<FrameRequest> last_;  // what `repeat` renders again
  std::chrono::steady_clock::time_point repeat_start_;
  std::vector<double> finish_times_;
  uint64_t sequence_ = 0;  // the worker thread's own
  std::thread thread_;
};

// What identifies a prepared technique: its name, every option value and the context.
std::string preparedKey(const TechniqueConfig& technique, const RenderContext& context);

}  // namespace penumbra::viewer
