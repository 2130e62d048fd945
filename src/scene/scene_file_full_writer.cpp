// Writes a whole scene as a scene file with its meshes and prototypes as OBJ files beside it
// (scene_file.h, writeSceneFile): how a scene built in code, a built-in city included, becomes
// a file with its instances kept as instances.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/scene_file.h"
#include "scene/write_obj.h"

namespace penumbra {

namespace {

namespace fs = std::filesystem;
using FullJson = nlohmann::ordered_json;

// As in scene_file_writer.cpp: through double, so that the text reads back as the same float.
FullJson vectorValue(const vec3& v) {
  return FullJson::array({double(v.x), double(v.y), double(v.z)});
}

FullJson materialValue(const Material& m) {
  return {{"name", m.name},
          {"albedo", vectorValue(m.albedo)},
          {"specular", vectorValue(m.specular)},
          {"shininess", double(m.shininess)}};
}

FullJson matrixValue(const mat4& m) {
  FullJson rows = FullJson::array();
  for (int row = 0; row < 3; ++row) {
    rows.push_back({double(m[0][row]), double(m[1][row]), double(m[2][row]), double(m[3][row])});
  }
  return rows;
}

// The OBJ is named by its place in the folder; the entry keeps the mesh's own name.
FullJson meshEntry(const Mesh& mesh, const fs::path& folder, const std::string& relative) {
  writeObj((folder / relative).string(), mesh,
           {"written by penumbra (writeSceneFile): " + mesh.name});
  return {{"name", mesh.name},
          {"file", (folder.filename() / relative).generic_string()},
          {"material", mesh.material}};
}

}  // namespace

void writeSceneFile(const std::string& path, const Scene& scene) {
  PENUMBRA_CHECK(fs::path(path).extension() == ".json", "{}: a scene file must end in .json", path);
  PENUMBRA_CHECK(scene.instance_meshes <= scene.meshes.size(),
                 "{}: the scene counts {} instance meshes but has {} meshes", path,
                 scene.instance_meshes, scene.meshes.size());
  const fs::path folder = fs::path(path).replace_extension().string() + "-meshes";
  std::error_code ec;
  fs::create_directories(folder / "meshes", ec);
  fs::create_directories(folder / "prototypes", ec);
  PENUMBRA_CHECK(!ec, "{}: cannot create the folder {}", path, folder.string());

  // Camera, lights and settings as the writer over a base writes them, so both agree.
  FullJson doc = FullJson::parse(sceneOverBaseJson(scene, "unused"));
  doc.erase("base");
  FullJson materials = FullJson::array();
  for (const Material& m : scene.materials) materials.push_back(materialValue(m));
  FullJson meshes = FullJson::array();
  for (size_t i = 0; i + scene.instance_meshes < scene.meshes.size(); ++i) {
    meshes.push_back(meshEntry(scene.meshes[i], folder, fmt::format("meshes/{}.obj", i)));
  }
  FullJson prototypes = FullJson::array();
  for (size_t i = 0; i < scene.prototypes.size(); ++i) {
    // Prototypes are named uniquely by the reader; the index keeps names unique whatever made
    // the scene.
    FullJson entry = meshEntry(*scene.prototypes[i], folder, fmt::format("prototypes/{}.obj", i));
    entry["name"] = fmt::format("{}:{}", i, scene.prototypes[i]->name);
    prototypes.push_back(std::move(entry));
  }
  std::string text = "{\n";
  const auto line = [&](const char* key, const FullJson& value, bool last = false) {
    text += fmt::format("  \"{}\": {}{}\n", key, value.dump(), last ? "" : ",");
  };
  line("name", doc["name"]);
  line("camera", doc["camera"]);
  line("lights", doc["lights"]);
  line("materials", materials);
  line("meshes", meshes);
  if (!scene.instances.empty()) {
    line("prototypes", prototypes);
    // One instance a line: a city's file is read and diffed by people too.
    text += "  \"instances\": [\n";
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      const MeshInstance& instance = scene.instances[i];
      FullJson entry = {{"prototype", instance.prototype},
                        {"matrix", matrixValue(instance.transform)},
                        {"material", instance.material}};
      if (!instance.name.empty()) entry["name"] = instance.name;
      text += "    " + entry.dump() + (i + 1 < scene.instances.size() ? ",\n" : "\n");
    }
    text += "  ],\n";
  }
  if (doc.contains("path")) line("path", doc["path"]);
  line("settings", doc["settings"], true);
  text += "}\n";

  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out.good()) {
      fs::remove(partial, ec);
      throw Error(fmt::format("{}: cannot write the scene file", path));
    }
  }
  fs::rename(partial, path, ec);
  PENUMBRA_CHECK(!ec, "{}: cannot move {} into place", path, partial);
}

}  // namespace penumbra
