// penumbra.render (one frame, the technique prepared for it) and Renderer (prepared once, frame
// after frame). Both release the GIL while the library works, so Python threads render at once.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "frame_result.h"

namespace penumbra::python {

namespace {

using OptionTexts = std::map<std::string, std::string>;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The frame options that are not the technique's: the culling switches and the eye pass's delay
// stream, as `penumbra render` has them (--occlusion-culling, --caster-culling, --delay-stream).
struct FrameSwitches {
  std::string occlusion_culling = "auto";  // off, on, auto
  std::string caster_culling = "auto";  // off, on, auto
  long long delay_stream = 0;  // bytes; 0: none
};

// The frame's settings; technique options by name (tile_size or tile-size) with values as the
// command line takes them.
FrameOptions makeFrameOptions(const std::string& technique, int width, int height, int threads,
                              bool simd, const FrameSwitches& switches,
                              const OptionTexts& options) {
  PENUMBRA_CHECK(width >= 0 && height >= 0, "frame size {}x{} is negative", width, height);
  PENUMBRA_CHECK(threads >= 0, "threads {} is negative (0: all cores)", threads);
  PENUMBRA_CHECK(switches.delay_stream >= 0 && switches.delay_stream <= (1LL << 34),
                 "delay_stream {} bytes is outside 0..2^34 (0: no delay stream)",
                 switches.delay_stream);
  FrameOptions frame;
  frame.technique = TechniqueConfig(technique);
  for (const auto& [name, value] : options) {
    std::string flag = name;
    for (char& c : flag) c = c == '_' ? '-' : c;
    frame.technique.set(flag, value);
  }
  frame.technique.validate();
  frame.width = width;
  frame.height = height;
  frame.context.threads = threads;
  frame.context.simd = simd;
  frame.context.caster_culling = parseCasterCulling(switches.caster_culling);
  frame.occlusion_culling = parseOcclusionCulling(switches.occlusion_culling);
  frame.delay_stream_bytes = size_t(switches.delay_stream);
  return frame;
}

// Python may have changed the lights since the scene was loaded: the checks Scene::finalize
// made then, again, so that a bad value is an error rather than a wrong frame.
void checkLightsForFrame(const Scene& scene) {
  PENUMBRA_CHECK(!scene.lights.empty(), "scene '{}' has no lights", scene.name);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    PENUMBRA_CHECK(isFinite(l.center), "scene.lights[{}]: centre ({}, {}, {}) is not finite", i,
                   l.center.x, l.center.y, l.center.z);
    PENUMBRA_CHECK(std::isfinite(l.radius) && l.radius >= 0.0f,
                   "scene.lights[{}]: radius {} must be finite and >= 0", i, l.radius);
    PENUMBRA_CHECK(isFinite(l.color) && glm::all(glm::greaterThanEqual(l.color, vec3(0.0f))),
                   "scene.lights[{}]: colour must be finite and >= 0", i);
    PENUMBRA_CHECK(std::isfinite(l.intensity) && l.intensity >= 0.0f,
                   "scene.lights[{}]: intensity {} must be finite and >= 0", i, l.intensity);
    try {
      checkLightShape(l);
    } catch (const Error& e) {
      throw Error(fmt::format("scene.lights[{}]: {}", i, e.what()));
    }
  }
}

// A technique prepared once for a scene. The scene's camera and lights may change between
// frames; its geometry cannot (Python offers no way to change it).
class Renderer {
 public:
  Renderer(std::shared_ptr<Scene> scene, FrameOptions options) : scene_(std::move(scene)) {
    py::gil_scoped_release release;
    renderer_ = std::make_unique<FrameRenderer>(*scene_, std::move(options));
  }

  py::object render() {
    checkLightsForFrame(*scene_);
    std::shared_ptr<FrameResult> frame = freeFrame();
    double render_ms = 0;
    {
      py::gil_scoped_release release;
      // One frame at a time per renderer: its shading table fills in as frames need it.
      const std::lock_guard<std::mutex> lock(mutex_);
      const auto start = std::chrono::steady_clock::now();
      renderer_->render(*frame);
      render_ms = msSince(start);
    }
    return wrapFrame(std::move(frame), 0.0, render_ms);
  }

  const std::shared_ptr<Scene>& scene() const { return scene_; }
  double prepareMs() const { return renderer_->prepareMs(); }
  std::string technique() const { return renderer_->options().technique.describe(); }

 private:
  // A frame no Python object holds any more (its buffers are overwritten, keeping their memory,
  // as the CLI's frame loop does), else a new one. Two are kept: `frame = renderer.render()`
  // in a loop holds the previous frame while the next one renders.
  std::shared_ptr<FrameResult> freeFrame() {
    for (const std::shared_ptr<FrameResult>& frame : frames_) {
      if (frame.use_count() == 1) return frame;
    }
    auto frame = std::make_shared<FrameResult>();
    if (frames_.size() < 2) frames_.push_back(frame);
    return frame;
  }

  std::shared_ptr<Scene> scene_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::vector<std::shared_ptr<FrameResult>> frames_;
  std::mutex mutex_;
};

}  // namespace

void bindRender(py::module_& m) {
  bindFrame(m);
  m.def(
      "_render",
      [](const std::shared_ptr<Scene>& scene, const std::string& technique, int width, int height,
         int threads, bool simd, const std::string& occlusion_culling,
         const std::string& caster_culling, long long delay_stream, const OptionTexts& options) {
        const FrameOptions frame_options = makeFrameOptions(
            technique, width, height, threads, simd,
            FrameSwitches{occlusion_culling, caster_culling, delay_stream}, options);
        checkLightsForFrame(*scene);
        auto frame = std::make_shared<FrameResult>();
        double render_ms = 0;
        {
          py::gil_scoped_release release;
          const auto start = std::chrono::steady_clock::now();
          *frame = renderFrame(*scene, frame_options);
          render_ms = msSince(start);
        }
        const double prepare_ms = frame->total.time_ms.front().second;  // renderFrame's "prepare"
        return wrapFrame(std::move(frame), prepare_ms, render_ms);
      },
      py::arg("scene"), py::arg("technique"), py::arg("width"), py::arg("height"),
      py::arg("threads"), py::arg("simd"), py::arg("occlusion_culling"),
      py::arg("caster_culling"), py::arg("delay_stream"), py::arg("options"));

  py::class_<Renderer>(m, "_Renderer")
      .def(py::init([](std::shared_ptr<Scene> scene, const std::string& technique, int width,
                       int height, int threads, bool simd, const std::string& occlusion_culling,
                       const std::string& caster_culling, long long delay_stream, const OptionTexts& options) {
             return std::make_unique<Renderer>(
                 std::move(scene),
                 makeFrameOptions(technique, width, height, threads, simd,
                                  FrameSwitches{occlusion_culling, caster_culling, delay_stream},
                                  options));
           }),
           py::arg("scene"), py::arg("technique"), py::arg("width"), py::arg("height"),
           py::arg("threads"), py::arg("simd"), py::arg("occlusion_culling"),
           py::arg("caster_culling"), py::arg("delay_stream"), py::arg("options"))
      .def("render", &Renderer::render)
      .def_property_readonly("scene", &Renderer::scene)
      .def_property_readonly("prepare_ms", &Renderer::prepareMs)
      .def_property_readonly("technique", &Renderer::technique);
}

}  // namespace penumbra::python
