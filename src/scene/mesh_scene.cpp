// Scenes around one mesh file, and resolution of a command-line scene argument.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include <assimp/Importer.hpp>
#include <fmt/ranges.h>

#include "core/error.h"
#include "core/path_extension.h"
#include "scene/builtin_scenes.h"
#include "scene/generators.h"
#include "scene/load_mesh.h"
#include "scene/mesh_ops.h"
#include "scene/scene_builder.h"
#include "scene/scene_file.h"

namespace penumbra {

namespace {

namespace fs = std::filesystem;

// The mesh is normalised to this many units along its largest extent.
constexpr float kMeshSize = 2.0f;

}  // namespace

Scene sceneForMesh(const std::string& path, UpAxis up) {
  Mesh mesh = loadMesh(path);
  if (up != UpAxis::Y) transformMesh(mesh, upAxisToY(up));
  // Stand the mesh on y = 0, centred on the vertical axis, kMeshSize units along its largest
  // extent, keeping proportions (meshes come in any unit: the bunny is 0.15 wide, the npm teapot
  // 32).
  const Bounds3 b = mesh.bounds();
  const vec3 extent = b.extent();
  const float largest = std::max({extent.x, extent.y, extent.z});
  const float scale = largest > 0.0f ? kMeshSize / largest : 1.0f;
  const vec3 c = b.center();
  transformMesh(mesh, glm::scale(mat4(1.0f), vec3(scale)) *
                          glm::translate(mat4(1.0f), vec3(-c.x, -b.min.y, -c.z)));

  Scene scene;
  scene.name = fs::path(path).stem().string();
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.72f, 0.71f, 0.68f));
  const uint32_t body = addMaterial(scene, "mesh", vec3(0.80f, 0.62f, 0.45f), vec3(0.25f), 40.0f);
  const Bounds3 framed = mesh.bounds();
  addMesh(scene, std::move(mesh), body);
  // The floor sits a hair below the mesh so a flat bottom does not z-fight with it.
  addMesh(scene, makeGroundPlane(vec3(0.0f, -0.002f * kMeshSize, 0.0f), 6.0f * kMeshSize), floor);
  // Light above, in front and to the left; the camera sees from front right, so the shadow
  // falls back and to the right where it is visible.
  const float height = framed.extent().y;
  addLight(scene, vec3(-1.6f, 2.4f + height, 2.2f) * (kMeshSize / 2.0f), 0.15f * kMeshSize);
  Bounds3 view_bounds = framed;
  view_bounds.extend(vec3(0.6f, 0.0f, -0.6f) * kMeshSize);  // the start of the shadow behind
  scene.camera = frameBounds(view_bounds, vec3(0.9f, 0.55f, 1.1f), scene.settings.width,
                             scene.settings.height, 40.0f, 0.85f);
  scene.finalize();
  return scene;
}

Scene loadScene(const std::string& name_or_path, UpAxis mesh_up) {
  const std::string ext = lowerExtension(name_or_path);
  const bool mesh_file = !isBuiltinScene(name_or_path) && ext != ".json" && !ext.empty() &&
                         Assimp::Importer().IsExtensionSupported(ext);
  // A scene names each mesh's up axis itself ("up" in a mesh entry); one axis for all would
  // turn its generated floor too.
  PENUMBRA_CHECK(mesh_up == UpAxis::Y || mesh_file,
                 "{}: an up axis other than y applies to a mesh file; in a scene file give "
                 "\"up\" in each mesh entry",
                 name_or_path);
  if (isBuiltinScene(name_or_path)) return builtinScene(name_or_path);
  if (ext == ".json") return loadSceneFile(name_or_path);
  if (mesh_file) return sceneForMesh(name_or_path, mesh_up);
  throw Error(fmt::format(
      "unknown scene '{}': not a built-in scene ({}), a .json scene file or a mesh file "
      "(.obj, .ply, .gltf, .glb, .stl, .off, .fbx, ...)",
      name_or_path, fmt::join(builtinSceneNames(), ", ")));
}

}  // namespace penumbra
