// Writes a scene's camera, lights and settings as a scene file over a base scene
// (scene/scene_file.h): what the viewer saves, and what `penumbra render` reads back.
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image_io.h"
#include "scene/scene_file.h"

namespace penumbra {

namespace {

using WriterJson = nlohmann::ordered_json;

// A float goes through double, whose shortest decimal text nlohmann writes: parsing it gives
// the same double, and so the same float (scene_file.cpp reads numbers as double).
WriterJson vectorJson(const vec3& v) {
  return WriterJson::array({double(v.x), double(v.y), double(v.z)});
}

WriterJson textureJson(const LightTexture& texture) {
  WriterJson texels = WriterJson::array();
  for (const vec3& t : texture.texels) texels.push_back(vectorJson(t));
  return {{"width", texture.width}, {"height", texture.height}, {"texels", std::move(texels)}};
}

WriterJson lightJson(const Light& light) {
  WriterJson entry;
  entry["center"] = vectorJson(light.center);
  entry["shape"] = lightShapeName(light.shape);
  if (light.shape == LightShape::Rectangle) {
    entry["u"] = vectorJson(light.edge_u);
    entry["v"] = vectorJson(light.edge_v);
    if (light.texture) entry["texture"] = textureJson(*light.texture);
  } else {
    entry["radius"] = double(light.radius);
  }
  if (light.shape == LightShape::Disk) entry["normal"] = vectorJson(light.normal);
  entry["color"] = vectorJson(light.color);
  entry["intensity"] = double(light.intensity);
  return entry;
}

// Written only when the scene has one; floats through double as above.
WriterJson pathJson(const ScenePath& path) {
  WriterJson doc = {{"frames", path.frames}};
  if (!path.camera.empty()) {
    WriterJson keys = WriterJson::array();
    for (const CameraKey& key : path.camera) {
      keys.push_back({{"time", double(key.time)},
                      {"position", vectorJson(key.position)},
                      {"target", vectorJson(key.target)},
                      {"fov", double(key.fov_y)}});
    }
    doc["camera"] = std::move(keys);
  }
  if (!path.lights.empty()) {
    WriterJson lights = WriterJson::array();
    for (const LightPath& light : path.lights) {
      WriterJson keys = WriterJson::array();
      for (const LightKey& key : light.keys) {
        keys.push_back({{"time", double(key.time)}, {"center", vectorJson(key.center)}});
      }
      lights.push_back({{"light", light.light}, {"keys", std::move(keys)}});
    }
    doc["lights"] = std::move(lights);
  }
  return doc;
}

}  // namespace

std::string sceneOverBaseJson(const Scene& scene, const std::string& base) {
  PENUMBRA_CHECK(!base.empty(), "a scene file over a base needs the base's name or path");
  const WriterJson camera = {{"position", vectorJson(scene.camera.position)},
                             {"target", vectorJson(scene.camera.target)},
                             {"up", vectorJson(scene.camera.up)},
                             {"fov", double(scene.camera.fov_y)},
                             {"near", double(scene.camera.near_plane)}};
  const WriterJson settings = {{"width", scene.settings.width},
                               {"height", scene.settings.height},
                               {"ambient", vectorJson(scene.settings.ambient)},
                               {"background", vectorJson(scene.settings.background)}};
  // One line per section and per light, as the hand-written files in scenes/ are laid out.
  std::string text = "{\n";
  text += "  \"name\": " + WriterJson(scene.name).dump() + ",\n";
  text += "  \"base\": " + WriterJson(base).dump() + ",\n";
  text += "  \"camera\": " + camera.dump() + ",\n";
  text += "  \"lights\": [\n";
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    text +=
        "    " + lightJson(scene.lights[i]).dump() + (i + 1 < scene.lights.size() ? ",\n" : "\n");
  }
  text += "  ],\n";
  if (!scene.path.empty()) text += "  \"path\": " + pathJson(scene.path).dump() + ",\n";
  text += "  \"settings\": " + settings.dump() + "\n";
  return text + "}\n";
}

void writeSceneOverBase(const std::string& path, const Scene& scene, const std::string& base) {
  const std::string text = sceneOverBaseJson(scene, base);
  createParentDirectories(path);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  PENUMBRA_CHECK(out.good(), "{}: cannot write the scene file", path);
}

}  // namespace penumbra
