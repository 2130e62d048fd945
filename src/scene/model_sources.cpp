#include "scene/model_sources.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "scene/json_reader.h"

namespace penumbra {

std::vector<std::string> sceneFileModels(const std::string& scene_path) {
  std::ifstream in(scene_path, std::ios::binary);
  PENUMBRA_CHECK(in.good(), "{}: cannot read the scene file", scene_path);
  std::ostringstream text;
  text << in.rdbuf();
  const Json doc = JsonReader(scene_path).parse(text.str());
  std::vector<std::string> models;
  const Json* meshes = doc.is_object() ? JsonReader::find(doc, "meshes") : nullptr;
  if (meshes == nullptr || !meshes->is_array()) return models;
  constexpr std::string_view kPrefix = "models:";
  for (const Json& mesh : *meshes) {
    const Json* file = mesh.is_object() ? JsonReader::find(mesh, "file") : nullptr;
    if (file == nullptr || !file->is_string()) continue;
    const std::string name = file->get<std::string>();
    if (name.starts_with(kPrefix)) models.push_back(name.substr(kPrefix.size()));
  }
  return models;
}

std::vector<std::string> fetchableModels(const std::string& table_path) {
  std::ifstream in(table_path);
  std::vector<std::string> models;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    models.push_back(line.substr(0, line.find('\t')));
  }
  return models;
}

}  // namespace penumbra
