#include "frame_worker.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

namespace penumbra::viewer {

std::string preparedKey(const TechniqueConfig& technique, const RenderContext& context) {
  std::string key = technique.name();
  for (const OptionSpec& spec : technique.info().options.specs()) {
    key += fmt::format(" {}={}", spec.name, technique.get(spec.name));
  }
  return key + fmt::format(" threads={} simd={} layers={}", context.threads, context.simd,
                           context.debug_layers);
}

FrameWorker::FrameWorker(Scene scene) : scene_(std::move(scene)) {
  thread_ = std::thread([this] { run(); });
}

FrameWorker::~FrameWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void FrameWorker::submit(FrameRequest request) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(request);
  }
  wake_.notify_all();
}

std::optional<DeliveredFrame> FrameWorker::take() {
  std::lock_guard lock(mutex_);
  std::optional<DeliveredFrame> frame = std::move(finished_);
  finished_.reset();
  return frame;
}

void FrameWorker::waitForFrame(int milliseconds) {
  std::unique_lock lock(mutex_);
  delivered_.wait_for(lock, std::chrono::milliseconds(milliseconds),
                      [this] { return finished_.has_value() || (!pending_ && !rendering_); });
}

void FrameWorker::setRepeat(bool repeat) {
  {
    std::lock_guard lock(mutex_);
    repeat_ = repeat;
    repeat_start_ = std::chrono::steady_clock::now();
    finish_times_.clear();
  }
  wake_.notify_all();
}

std::vector<double> FrameWorker::finishTimes() const {
  std::lock_guard lock(mutex_);
  return finish_times_;
}

bool FrameWorker::busy() const {
  std::lock_guard lock(mutex_);
  return pending_.has_value() || rendering_;
}

void FrameWorker::run() {
  for (;;) {
    FrameRequest request;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || pending_.has_value() || (repeat_ && last_); });
      if (stop_) return;
      if (pending_) {
        request = std::move(*pending_);
        pending_.reset();
      } else {
        request = *last_;
      }
      last_ = request;
      rendering_ = true;
    }
    DeliveredFrame frame = render(request);
    {
      std::lock_guard lock(mutex_);
      finished_ = std::move(frame);
      rendering_ = false;
      if (repeat_) {
        finish_times_.push_back(std::chrono::duration<double, std::milli>(
                                    std::chrono::steady_clock::now() - repeat_start_)
                                    .count());
      }
    }
    delivered_.notify_all();
  }
}

std::shared_ptr<FrameResult> FrameWorker::recycledFrame() {
  // A frame nobody else holds any more keeps its buffers: rendering into it again does not
  // allocate and page-fault a new image (FrameRenderer::render reuses same-sized ones).
  for (const std::shared_ptr<FrameResult>& frame : pool_) {
    if (frame.use_count() == 1) return frame;
  }
  pool_.push_back(std::make_shared<FrameResult>());
  return pool_.back();
}

FrameRenderer& FrameWorker::preparedRenderer(const FrameRequest& request,
                                             DeliveredFrame& delivered) {
  constexpr size_t kKept = 3;  // the full frame, its preview, and one more (layers on or off)
  const std::string key = preparedKey(request.technique, request.context);
  auto found = std::find_if(renderers_.begin(), renderers_.end(),
                            [&](const auto& entry) { return entry.first == key; });
  if (found == renderers_.end()) {
    if (renderers_.size() == kKept) renderers_.pop_back();
    auto renderer = std::make_unique<FrameRenderer>(
        scene_, FrameOptions{request.technique, 0, 0, request.context});
    delivered.prepare_ms = renderer->prepareMs();
    renderers_.emplace(renderers_.begin(), key, std::move(renderer));
  } else {
    std::rotate(renderers_.begin(), found, found + 1);
  }
  return *renderers_.front().second;
}

DeliveredFrame FrameWorker::render(const FrameRequest& request) {
  DeliveredFrame delivered;
  delivered.generation = request.generation;
  delivered.sequence = ++sequence_;
  delivered.preview = request.preview;
  delivered.preview_options = request.preview_options;
  try {
    // Preparing depends on the geometry only (the oracle's BVH, say), which never changes here:
    // a new camera, new lights or a new size reuse the prepared technique.
    FrameRenderer& renderer = preparedRenderer(request, delivered);
    // The renderer reads the scene's camera, lights and size at every frame (width 0 above).
    scene_.camera = request.camera;
    scene_.lights = request.lights;
    scene_.settings.width = request.width;
    scene_.settings.height = request.height;
    std::shared_ptr<FrameResult> frame = recycledFrame();
    const auto start = std::chrono::steady_clock::now();
    renderer.render(*frame);
    delivered.render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    delivered.frame = std::move(frame);
  } catch (const std::exception& e) {
    delivered.error = e.what();
  }
  return delivered;
}

}  // namespace penumbra::viewer
