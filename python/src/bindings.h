#pragma once
// What the module's files share: the functions that bind each part, and the types that cross
// into Python by reference rather than as copies.
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl_bind.h>

#include <penumbra/penumbra.h>

#include "vec3_caster.h"

// scene.lights is the scene's own vector, so `scene.lights[0].radius = 0.5` changes the light
// the next frame sees (with pybind11's list conversion it would change a copy).
PYBIND11_MAKE_OPAQUE(std::vector<penumbra::Light>)

namespace penumbra::python {

namespace py = pybind11;

void bindScene(py::module_& m);       // bind_scene.cpp: Scene, Camera, Light, loading
void bindTechniques(py::module_& m);  // bind_techniques.cpp: the technique table
void bindRender(py::module_& m);      // bind_render.cpp: render, Renderer, Frame
void bindImages(py::module_& m);      // bind_images.cpp: compare, read_image

}  // namespace penumbra::python
