#include "oracle_worker.h"

namespace penumbra::viewer {

OracleWorker::OracleWorker(Scene scene) : scene_(std::move(scene)) {
  thread_ = std::thread([this] { run(); });
}

OracleWorker::~OracleWorker() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void OracleWorker::restart(uint64_t generation, std::shared_ptr<const FrameResult> frame,
                           std::vector<Light> lights, size_t light) {
  {
    std::lock_guard lock(mutex_);
    if (active_ && generation == generation_ && light == light_) return;
    generation_ = generation;
    light_ = light;
    lights_ = std::move(lights);
    frame_ = std::move(frame);
    latest_.reset();
    active_ = true;
    ++restarts_;
  }
  wake_.notify_all();
}

void OracleWorker::stop() {
  std::lock_guard lock(mutex_);
  active_ = false;
  latest_.reset();
}

std::optional<OracleImage> OracleWorker::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

void OracleWorker::run() {
  Image<float> sum;
  int passes = 0;
  uint64_t generation = 0;
  size_t light = 0;
  uint64_t restarts = 0;
  for (;;) {
    std::shared_ptr<const FrameResult> frame;
    Light shown_light;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] {
        return quit_ || (active_ && (restarts_ != restarts || passes < kMaxPasses));
      });
      if (quit_) return;
      if (restarts_ != restarts) {
        restarts = restarts_;
        generation = generation_;
        light = light_;
        passes = 0;
      }
      frame = frame_;
      shown_light = lights_.at(light);
    }
    // One pass with its own seed. The options (seed included) are fixed when the oracle is
    // prepared, so each pass prepares it afresh (its BVH build is small next to a pass of 64
    // rays a pixel). It runs in a one-thread TBB arena: RenderContext::threads would limit the
    // whole process (a TBB global control), the frame worker included, which keeps the cores.
    ReferenceOptions options;
    options.rays = kRaysPerPass;
    options.seed = uint64_t(passes) + 1;
    TechniqueResult result;
    try {
      arena_.execute([&] {
        result = renderShadows(TechniqueConfig("reference", options), scene_, shown_light,
                               frame->view, frame->eye, RenderContext{});
      });
    } catch (const std::exception&) {
      std::lock_guard lock(mutex_);
      active_ = false;  // the oracle cannot render this light: compare mode shows no oracle
      continue;
    }
    if (passes == 0) sum = Image<float>(result.visibility.width(), result.visibility.height(), 0.0f);
    for (size_t i = 0; i < sum.size(); ++i) sum.data()[i] += result.visibility.data()[i];
    ++passes;
    OracleImage image{generation, light, passes, passes * kRaysPerPass,
                      Image<float>(sum.width(), sum.height(), 0.0f)};
    for (size_t i = 0; i < sum.size(); ++i) image.visibility.data()[i] = sum.data()[i] / float(passes);
    std::lock_guard lock(mutex_);
    // Published only when no restart came in meanwhile (else it belongs to an old view).
    if (restarts_ == restarts && active_) latest_ = std::move(image);
  }
}

}  // namespace penumbra::viewer
