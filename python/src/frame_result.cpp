#include "frame_result.h"

#include <string>
#include <utility>

namespace penumbra::python {

namespace {

// What the Python Frame object holds: arrays made once, all based on `owner`.
struct PyFrame {
  py::capsule owner;
  py::array color;
  py::list visibility;
  py::array depth;
  py::dict counters;
  py::dict times;
  double prepare_ms = 0;
  double render_ms = 0;
  int width = 0, height = 0;
};

py::array grayArray(const Image<float>& image, const py::capsule& owner) {
  return py::array_t<float>({image.height(), image.width()},
                            {ssize_t(image.width() * sizeof(float)), ssize_t(sizeof(float))},
                            image.data(), owner);
}

py::array colorArray(const Image<vec3>& image, const py::capsule& owner) {
  static_assert(sizeof(vec3) == 3 * sizeof(float), "colour pixels are three packed floats");
  return py::array_t<float>(
      {image.height(), image.width(), 3},
      {ssize_t(image.width() * sizeof(vec3)), ssize_t(sizeof(vec3)), ssize_t(sizeof(float))},
      reinterpret_cast<const float*>(image.data()), owner);
}

// Pass name -> milliseconds, summed over lights (each light's technique times its own passes),
// in the order the passes first ran.
py::dict passTimes(const Stats& stats) {
  py::dict times;
  for (const auto& [name, ms] : stats.time_ms) {
    const py::str key(name);
    times[key] = times.contains(key) ? times[key].cast<double>() + ms : ms;
  }
  return times;
}

}  // namespace

py::dict counterDict(const Stats& stats) {
  py::dict counters;
  stats.forEachCounter(
      [&](const char* name, const char*, uint64_t value) { counters[name] = value; });
  return counters;
}

py::object wrapFrame(std::shared_ptr<FrameResult> frame, double prepare_ms, double render_ms) {
  PyFrame out;
  const FrameResult& f = *frame;
  out.owner = py::capsule(new std::shared_ptr<FrameResult>(std::move(frame)), [](void* p) {
    delete static_cast<std::shared_ptr<FrameResult>*>(p);
  });
  out.color = colorArray(f.color, out.owner);
  for (const TechniqueResult& light : f.lights) {
    out.visibility.append(grayArray(light.visibility, out.owner));
  }
  out.depth = grayArray(f.eye.depth.depth, out.owner);
  out.counters = counterDict(f.total);
  out.times = passTimes(f.total);
  out.prepare_ms = prepare_ms;
  out.render_ms = render_ms;
  out.width = f.color.width();
  out.height = f.color.height();
  return py::cast(std::move(out));
}

void bindFrame(py::module_& m) {
  py::class_<PyFrame>(m, "Frame",
                      "A rendered frame. Its arrays are views of the frame's own buffers.")
      .def_readonly("color", &PyFrame::color, "H x W x 3 float32, linear RGB, shaded.")
      .def_readonly("visibility", &PyFrame::visibility,
                    "One H x W float32 array per light (scene.lights order): the fraction of "
                    "the light each pixel's visible point sees, 1 on the background.")
      .def_readonly("depth", &PyFrame::depth,
                    "H x W float32 reversed-Z depth: near / distance, 0 on the background.")
      .def_readonly("counters", &PyFrame::counters,
                    "Work counters of the whole frame (eye pass and every light), by name.")
      .def_readonly("times", &PyFrame::times,
                    "Milliseconds per pass, summed over lights; 'prepare' when the technique was "
                    "prepared for this frame (penumbra.render).")
      .def_readonly("prepare_ms", &PyFrame::prepare_ms)
      .def_readonly("render_ms", &PyFrame::render_ms,
                    "Wall-clock milliseconds of the library's call that rendered the frame "
                    "(preparation included for penumbra.render), without the binding's work.")
      .def_readonly("width", &PyFrame::width)
      .def_readonly("height", &PyFrame::height)
      .def_property_readonly("frame_ms",
                             [](const PyFrame& f) {
                               double total = 0;
                               for (const auto& [name, ms] : f.times) {
                                 if (name.cast<std::string>() != "prepare") total += ms.cast<double>();
                               }
                               return total;
                             },
                             "The passes' milliseconds, without 'prepare'.")
      .def("__repr__", [](const PyFrame& f) {
        return fmt::format("Frame({}x{}, {} lights)", f.width, f.height, f.visibility.size());
      });
}

}  // namespace penumbra::python
