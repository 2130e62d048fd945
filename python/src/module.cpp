// The extension module penumbra._penumbra; python/penumbra/__init__.py is the package users
// import, which adds the scene dicts, the option keywords and the docstrings built from the
// technique table.
#include "bindings.h"

PYBIND11_MODULE(_penumbra, m) {
  using namespace penumbra::python;
  m.doc() = "Penumbra's C++ library: scenes, shadow techniques, frames, image comparison.";
  // Every penumbra::Error (bad input, bad options, unreadable files) arrives as penumbra.Error
  // with the library's message; it is a ValueError, as most are bad values.
  py::register_exception<penumbra::Error>(m, "Error", PyExc_ValueError);
  bindScene(m);
  bindTechniques(m);
  bindRender(m);
  bindImages(m);
}
