#pragma once
// A rendered frame as Python sees it: numpy arrays over the FrameResult's own buffers (no
// copies), its counters and pass times.
#include <memory>

#include "bindings.h"

namespace penumbra::python {

// The Python object for `frame`: its arrays share one capsule holding `frame`, so the frame
// lives while any array does, and `frame.use_count()` falls back to what the caller holds once
// Python has dropped them all (Renderer reuses such frames). `render_ms` is the wall-clock time
// of the library's call that rendered it, for measuring what the binding adds.
py::object wrapFrame(std::shared_ptr<FrameResult> frame, double prepare_ms, double render_ms);

// The work counters by name. The one place that walks the Stats counters, so that where they
// are declared can change without touching the rest of the module.
py::dict counterDict(const Stats& stats);

void bindFrame(py::module_& m);

}  // namespace penumbra::python
