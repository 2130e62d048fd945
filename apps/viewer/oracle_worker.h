#pragma once
// The oracle for compare mode, accumulated in the background: the `reference` technique renders
// the shown frame's visible points (its eye buffers) pass after pass, each pass with its own
// seed, and the running mean of the passes is the oracle so far. A new frame (the view or the
// lights changed) restarts it.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <tbb/task_arena.h>

#include <penumbra/penumbra.h>

namespace penumbra::viewer {

struct OracleImage {
  uint64_t generation = 0;
  size_t light = 0;
  int passes = 0;     // accumulated so far
  int rays = 0;       // per pixel, all passes together
  Image<float> visibility;
};

class OracleWorker {
 public:
  // Rays per pass and the most passes kept (then the oracle rests): 64 x 64 = 4096 rays, the
  // reference technique's most.
  static constexpr int kRaysPerPass = 64;
  static constexpr int kMaxPasses = 64;

  explicit OracleWorker(Scene scene);
  ~OracleWorker();
  OracleWorker(const OracleWorker&) = delete;
  OracleWorker& operator=(const OracleWorker&) = delete;

  // Restarts on `frame` (full resolution) for light `light`; the same generation and light
  // again keep accumulating.
  void restart(uint64_t generation, std::shared_ptr<const FrameResult> frame,
               std::vector<Light> lights, size_t light);
  void stop();  // compare mode off: no more passes
  // The newest accumulated image, if any for the current generation.
  std::optional<OracleImage> latest() const;

 private:
  void run();

  Scene scene_;
  tbb::task_arena arena_{1};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool quit_ = false;
  bool active_ = false;
  uint64_t restarts_ = 0;  // bumped by every restart: the passes so far belong to an old frame
  uint64_t generation_ = 0;
  size_t light_ = 0;
  std::vector<Light> lights_;
  std::shared_ptr<const FrameResult> frame_;
  std::optional<OracleImage> latest_;
  std::thread thread_;
};

}  // namespace penumbra::viewer
