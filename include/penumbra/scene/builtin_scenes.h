#pragma once
// Procedural scenes reproducing the papers' test scenes in spirit (DESIGN.md "Scenes").
#include <string>
#include <vector>

#include <penumbra/scene/scene.h>

namespace penumbra {

// "spheres", "columns", "fractal", "year2002", "multilight".
std::vector<std::string> builtinSceneNames();
bool isBuiltinScene(const std::string& name);
Scene builtinScene(const std::string& name);  // throws penumbra::Error for an unknown name

// A scene around one mesh file: the mesh framed by the camera, standing on a ground plane under
// a default light ("penumbra render some.obj").
Scene sceneForMesh(const std::string& path);

// Resolves a command-line scene argument: a built-in name, a .json scene file, or a mesh file.
Scene loadScene(const std::string& name_or_path);

}  // namespace penumbra
