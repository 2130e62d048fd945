#pragma once
// The JSON scene format, documented in docs/scene-format.md.
#include <string>
#include <vector>

#include <penumbra/scene/mesh_arrays.h>
#include <penumbra/scene/scene.h>

namespace penumbra {

// Reads a scene file. Relative mesh paths are relative to the scene file's folder; a path
// starting with "models:" is looked up with modelPath(). Throws penumbra::Error naming the
// file and the offending key.
Scene loadSceneFile(const std::string& path);
// Same, from JSON text; `origin` names the text in messages, `base_dir` resolves relative paths.
Scene parseSceneJson(const std::string& text, const std::string& origin,
                     const std::string& base_dir);
// Same, with meshes given in memory: a "meshes" entry {"arrays": i} takes arrays[i]
// (mesh_arrays.h), checked as meshFromArrays checks it, with the keys a file entry has besides
// "file" and "up" ("name", "material", "transform", "fit"). Without arrays such an entry is an
// error.
Scene parseSceneJson(const std::string& text, const std::string& origin,
                     const std::string& base_dir, const std::vector<MeshArrays>& arrays);

// A scene file holding `scene`'s camera, lights (every shape, textures inline) and settings over
// the base scene `base` (a built-in scene's name, or the path of a scene file or a mesh file,
// written as given; docs/scene-format.md, "base"): loading it gives `scene` back when `scene`'s
// meshes and materials are the base's. Numbers are written so that they read back bit for bit.
std::string sceneOverBaseJson(const Scene& scene, const std::string& base);
// Writes sceneOverBaseJson to `path` (its folders created); throws penumbra::Error naming the
// file when it cannot be written.
void writeSceneOverBase(const std::string& path, const Scene& scene, const std::string& base);

// Writes the whole of `scene` as a scene file at `path`: materials, lights, camera, settings,
// and its geometry as OBJ files in the folder `<path without .json>-meshes/` beside it (each
// mesh that is not an instance copy as meshes/<i>.obj, each prototype once as
// prototypes/<i>.obj) with the instances as "matrix" entries. Loading it gives the same
// positions, triangles, instance transforms and materials bit for bit (shading normals are
// recomputed by the loader). Throws penumbra::Error naming the file that cannot be written.
void writeSceneFile(const std::string& path, const Scene& scene);

// The folder "models:NAME" paths are looked up in, the first of: $PENUMBRA_MODELS when set;
// ../shared/models beside the source tree when that folder exists (developers); the user's
// cache, userModelsCache(), which scripts/fetch-models.sh fills.
std::string modelsDirectory();
// $XDG_CACHE_HOME/penumbra/models, else ~/.cache/penumbra/models.
std::string userModelsCache();
// The models/ folder of the source tree: the models whose licences let the repository ship them.
std::string shippedModelsDirectory();
// Where "models:NAME" is read from: modelsDirectory()/NAME when it exists there, else
// shippedModelsDirectory()/NAME when it exists there, else modelsDirectory()/NAME (absent; the
// caller reports it). The models folder comes first so that PENUMBRA_MODELS can override.
std::string modelPath(const std::string& name);

}  // namespace penumbra
