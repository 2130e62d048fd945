#pragma once
// Procedural scenes reproducing the papers' test scenes in spirit (README, "What is in it").
#include <string>
#include <vector>

#include <penumbra/scene/scene.h>
#include <penumbra/scene/up_axis.h>

namespace penumbra {

// "spheres", "columns", "fractal", "year2002", "multilight": the scenes every technique's tests
// render.
std::vector<std::string> builtinSceneNames();
// "city", "interior": built-in scenes too large for those tests at their default size. Each
// also takes a size, "city:N" (N x N blocks, 1..64; "city" is city:8, 2 million triangles;
// city:20 holds over 10 million, city:64 over 100 million), "interior:N" (a hall of N x N bays,
// 1..64; "interior" is interior:4); the tests render "city:1" and "interior:1".
std::vector<std::string> largeBuiltinSceneNames();
// True for the names of both lists and for every "city:..." and "interior:..." (a bad size is
// builtinScene's error).
bool isBuiltinScene(const std::string& name);
Scene builtinScene(const std::string& name);  // throws penumbra::Error for an unknown name or size

// A scene around one mesh file: the mesh framed by the camera, standing on a ground plane under
// a default light ("penumbra render some.obj"); `up` is the file's up axis.
Scene sceneForMesh(const std::string& path, UpAxis up = UpAxis::Y);

// Resolves a command-line scene argument: a built-in name, a .json scene file, or a mesh file,
// whose up axis is `mesh_up` (anything but y for the others is an error).
Scene loadScene(const std::string& name_or_path, UpAxis mesh_up = UpAxis::Y);

}  // namespace penumbra
