// Scenes, their camera and lights as Python objects. The camera and the lights are the scene's
// own (changed in place): a Renderer sees the changes at its next frame. Geometry is read-only,
// since a prepared technique holds state built from it (the oracle's BVH).
#include <memory>
#include <string>
#include <utility>

#include "bindings.h"

namespace penumbra::python {

namespace {

LightShape parseLightShape(const std::string& text) {
  for (LightShape shape : {LightShape::Sphere, LightShape::Disk, LightShape::Rectangle}) {
    if (lightShapeName(shape) == text) return shape;
  }
  throw Error(fmt::format("light shape '{}' is not one of sphere, disk, rectangle", text));
}

void bindCamera(py::module_& m) {
  py::class_<Camera>(m, "Camera", "The scene's pinhole camera (world units, degrees).")
      .def(py::init<>())
      .def_readwrite("position", &Camera::position, "The eye's position.")
      .def_readwrite("target", &Camera::target, "The point the camera looks at.")
      .def_readwrite("up", &Camera::up, "The up direction of the image.")
      .def_readwrite("fov", &Camera::fov_y, "Vertical field of view in degrees.")
      .def_readwrite("near", &Camera::near_plane, "Near plane distance (reversed-Z depth = near / distance).")
      .def("__repr__", [](const Camera& c) {
        return fmt::format("Camera(position=({}, {}, {}), target=({}, {}, {}), fov={})",
                           c.position.x, c.position.y, c.position.z, c.target.x, c.target.y,
                           c.target.z, c.fov_y);
      });
}

void bindLight(py::module_& m) {
  py::class_<Light>(m, "Light",
                    "An area light: a sphere (centre, radius; radius 0 is a point light), a "
                    "disk (centre, radius, normal) or a rectangle (centre, edge_u, edge_v).")
      .def(py::init([](vec3 center, float radius, vec3 color, float intensity) {
             Light light;
             light.center = center;
             light.radius = radius;
             light.color = color;
             light.intensity = intensity;
             checkLightShape(light);
             return light;
           }),
           py::arg("center") = vec3(0.0f, 10.0f, 0.0f), py::arg("radius") = 0.0f,
           py::arg("color") = vec3(1.0f), py::arg("intensity") = 1.0f)
      .def_readwrite("center", &Light::center, "Centre in world space.")
      .def_readwrite("radius", &Light::radius,
                     "Radius (sphere, disk); a rectangle's is half its diagonal.")
      .def_readwrite("color", &Light::color, "Linear RGB.")
      .def_readwrite("intensity", &Light::intensity, "Scales color (no distance falloff).")
      .def_property(
          "shape", [](const Light& l) { return lightShapeName(l.shape); },
          [](Light& l, const std::string& shape) { l.shape = parseLightShape(shape); },
          "'sphere', 'disk' or 'rectangle'.")
      .def_readwrite("normal", &Light::normal, "A disk's unit normal.")
      .def_readwrite("edge_u", &Light::edge_u, "A rectangle's first full edge vector.")
      .def_readwrite("edge_v", &Light::edge_v, "A rectangle's second full edge vector.")
      .def("__repr__", [](const Light& l) {
        return fmt::format("Light(shape='{}', center=({}, {}, {}), radius={})",
                           lightShapeName(l.shape), l.center.x, l.center.y, l.center.z, l.radius);
      });
  py::bind_vector<std::vector<Light>>(m, "LightList", "The scene's lights, changed in place.");
  py::implicitly_convertible<py::list, std::vector<Light>>();
}

py::list meshSummaries(const Scene& scene) {
  py::list meshes;
  for (const Mesh& mesh : scene.meshes) {
    py::dict entry;
    entry["name"] = mesh.name;
    entry["triangles"] = mesh.triangleCount();
    entry["vertices"] = mesh.positions.size();
    entry["closed"] = mesh.closed;
    meshes.append(entry);
  }
  return meshes;
}

void bindSceneClass(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene", "A loaded scene (penumbra.load_scene).")
      .def_readonly("name", &Scene::name)
      .def_property(
          "camera", [](Scene& s) -> Camera& { return s.camera; },
          [](Scene& s, const Camera& c) { s.camera = c; }, py::return_value_policy::reference_internal,
          "The camera, changed in place (scene.camera.position = ...).")
      .def_property(
          "lights", [](Scene& s) -> std::vector<Light>& { return s.lights; },
          [](Scene& s, const std::vector<Light>& lights) { s.lights = lights; },
          py::return_value_policy::reference_internal,
          "The lights, changed in place (scene.lights[0].radius = ...).")
      .def_property(
          "width", [](const Scene& s) { return s.settings.width; },
          [](Scene& s, int w) { s.settings.width = w; }, "Default frame width.")
      .def_property(
          "height", [](const Scene& s) { return s.settings.height; },
          [](Scene& s, int h) { s.settings.height = h; }, "Default frame height.")
      .def_property_readonly("triangle_count", &Scene::triangleCount)
      .def_property_readonly("meshes", &meshSummaries,
                             "Per mesh: name, triangles, vertices (welded), closed.")
      .def_property_readonly(
          "bounds",
          [](const Scene& s) {
            const Bounds3 b = s.bounds();
            return py::make_tuple(b.min, b.max);
          },
          "(min, max) corners of the geometry's box.")
      .def("copy", [](const Scene& s) { return std::make_shared<Scene>(s); },
           "An independent copy (its own camera and lights).")
      .def("__repr__", [](const Scene& s) {
        return fmt::format("Scene('{}', {} meshes, {} triangles, {} lights)", s.name,
                           s.meshes.size(), s.triangleCount(), s.lights.size());
      });
}

MeshArrays toMeshArrays(const py::array_t<float, py::array::c_style | py::array::forcecast>& vertices,
                        const py::array_t<int64_t, py::array::c_style | py::array::forcecast>& triangles) {
  MeshArrays arrays;
  arrays.vertices.assign(vertices.data(), vertices.data() + vertices.size());
  arrays.triangles.assign(triangles.data(), triangles.data() + triangles.size());
  return arrays;
}

void bindLoading(py::module_& m) {
  m.def(
      "_load_scene",
      [](const std::string& name_or_path, const std::string& up) {
        const UpAxis axis = parseUpAxis(up);
        py::gil_scoped_release release;
        return std::make_shared<Scene>(loadScene(name_or_path, axis));
      },
      py::arg("name_or_path"), py::arg("up") = "y");
  m.def(
      "_parse_scene_json",
      [](const std::string& text, const std::string& origin, const std::string& base_dir,
         const py::list& mesh_arrays) {
        std::vector<MeshArrays> arrays;
        for (const py::handle pair : mesh_arrays) {
          const auto items = pair.cast<py::tuple>();
          arrays.push_back(toMeshArrays(items[0].cast<py::array_t<float, py::array::c_style | py::array::forcecast>>(),
                                        items[1].cast<py::array_t<int64_t, py::array::c_style | py::array::forcecast>>()));
        }
        py::gil_scoped_release release;
        return std::make_shared<Scene>(parseSceneJson(text, origin, base_dir, arrays));
      },
      py::arg("text"), py::arg("origin"), py::arg("base_dir"), py::arg("mesh_arrays"));
  m.def("builtin_scenes", &builtinSceneNames, "The built-in scenes' names.");
}

}  // namespace

void bindScene(py::module_& m) {
  bindCamera(m);
  bindLight(m);
  bindSceneClass(m);
  bindLoading(m);
}

}  // namespace penumbra::python
