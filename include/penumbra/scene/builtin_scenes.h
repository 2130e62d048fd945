#pragma once
// Procedural scenes reproducing the papers' test scenes in spirit (README, "What is in it").
#include <string>
#include <vector>

#include <penumbra/scene/scene.h>
#include <penumbra/scene/up_axis.h>

namespace penumbra {

// "spheres", "columns", "fractal", "year2002", "multilight".
std::vector<std::string> builtinSceneNames();
bool isBuiltinScene(const std::string& name);
Scene builtinScene(const std::string& name);  // throws penumbra::Error for an unknown name

// A scene around one mesh file: the mesh framed by the camera, standing on a ground plane under
// a default light ("penumbra render some.obj"); `up` is the file's up axis.
Scene sceneForMesh(const std::string& path, UpAxis up = UpAxis::Y);

// Resolves a command-line scene argument: a built-in name, a .json scene file, or a mesh file,
// whose up axis is `mesh_up` (anything but y for the others is an error).
Scene loadScene(const std::string& name_or_path, UpAxis mesh_up = UpAxis::Y);

}  // namespace penumbra
