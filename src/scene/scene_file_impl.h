#pragma once
// Internals of the scene file reader shared by scene_file.cpp and scene_file_meshes.cpp.
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/mesh_arrays.h"
#include "scene/scene.h"

namespace penumbra {

// Reads one entry of "meshes" (at key path `path`) and appends its mesh to scene.meshes;
// materials must already be read (names resolve against scene.materials). `arrays` are the
// in-memory meshes an {"arrays": i} entry may name (scene_file.h).
void readMeshEntry(const JsonReader& reader, const Json& entry, const std::string& path,
                   const std::string& base_dir, const std::vector<MeshArrays>& arrays,
                   Scene& scene);

// The mesh of one mesh entry (as readMeshEntry reads it) without appending it: the "prototypes"
// entries of scene_file_instances.cpp.
Mesh readMeshValue(const JsonReader& reader, const Json& entry, const std::string& path,
                   const std::string& base_dir, const std::vector<MeshArrays>& arrays,
                   const Scene& scene);

// A "transform" object (translate * rotate * scale) and a material reference (a name or an
// index into scene.materials), as mesh entries take them.
mat4 readTransformValue(const JsonReader& reader, const Json& value, const std::string& path);
uint32_t readMaterialValue(const JsonReader& reader, const Json& value, const std::string& path,
                           const Scene& scene);

// The "prototypes" and "instances" arrays of a scene file (scene_file_instances.cpp); materials
// must already be read. `instances` may be null (no instances given).
void readPrototypesAndInstances(const JsonReader& reader, const Json* prototypes,
                                const Json* instances, const std::string& base_dir,
                                const std::vector<MeshArrays>& arrays, Scene& scene);

// The "path" object (scene_file_path.cpp); the lights and camera must already be read.
void readScenePath(const JsonReader& reader, const Json& value, Scene& scene);

// A mesh "file" value to a path: "models:NAME" in modelsDirectory(), relative paths against
// base_dir, absolute paths as they are.
std::string resolveMeshPath(const std::string& file, const std::string& base_dir);

// False for "models:NAME" values whose NAME is absolute or climbs out with '..'; true for
// names inside the models folder and for values without the prefix.
bool isInsideModelsFolder(const std::string& file);

}  // namespace penumbra
