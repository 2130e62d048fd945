#include "timed_frames.h"

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "core/parallel.h"

namespace penumbra {

void renderUntimed(const PreparedTechnique& technique, const Scene& scene, const View& view,
                   const EyeBuffers& eye) {
  for (const Light& light : scene.lights) technique.render(light, view, eye, RenderContext{});
}

bool timeWarmFrames(benchmark::State& state, const FrameRenderer& renderer, FrameResult& frame) {
  renderer.render(frame);  // untimed (renderUntimed)
  std::map<std::string, double> pass_totals;
  std::vector<std::string> pass_order;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(frame);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(frame.color.data());
    for (const auto& [name, ms] : frame.total.time_ms) {
      if (!pass_totals.count(name)) pass_order.push_back(name);
      pass_totals[name] += ms;
    }
  }
  if (seconds <= 0.0) return false;
  const double frames = double(state.iterations());
  state.counters["fps"] = frames / seconds;
  state.counters["frame_ms"] = 1e3 * seconds / frames;
  for (const std::string& name : pass_order)
    state.counters[name + "_ms"] = pass_totals[name] / frames;
  state.counters["threads"] = double(workerCount());
  return true;
}

}  // namespace penumbra
