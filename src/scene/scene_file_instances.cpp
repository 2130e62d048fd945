// The "prototypes" and "instances" of a scene file: a mesh read once and placed many times
// (docs/scene-format.md, "instances").
#include <memory>
#include <set>

#include <fmt/ranges.h>

#include "core/error.h"
#include "scene/scene_file_impl.h"

namespace penumbra {

namespace {

// "matrix": three rows of four numbers, the affine map's top three rows (the fourth is 0 0 0 1).
mat4 readMatrix(const JsonReader& reader, const Json& value, const std::string& path) {
  const char* shape = "expected 3 rows of 4 numbers (the affine transform's top rows)";
  if (!value.is_array() || value.size() != 3) reader.fail(path, shape);
  mat4 m(1.0f);
  for (size_t row = 0; row < 3; ++row) {
    const std::string row_path = JsonReader::element(path, row);
    if (!value[row].is_array() || value[row].size() != 4) reader.fail(row_path, shape);
    for (size_t column = 0; column < 4; ++column) {
      m[int(column)][int(row)] =
          reader.number(value[row][column], JsonReader::element(row_path, column));
    }
  }
  return m;
}

uint32_t readPrototypeRef(const JsonReader& reader, const Json& value, const std::string& path,
                          const Scene& scene) {
  if (scene.prototypes.empty()) {
    reader.fail(path, "names a prototype, but the scene has no \"prototypes\"");
  }
  if (value.is_number_integer()) {
    const int index = reader.integer(value, path);
    if (index < 0 || size_t(index) >= scene.prototypes.size()) {
      reader.fail(path, fmt::format("prototype index {} is out of range (there are {} prototypes)",
                                    index, scene.prototypes.size()));
    }
    return uint32_t(index);
  }
  if (!value.is_string()) reader.fail(path, "expected a prototype name or index");
  const std::string name = value.get<std::string>();
  std::vector<std::string> names;
  for (size_t i = 0; i < scene.prototypes.size(); ++i) {
    if (scene.prototypes[i]->name == name) return uint32_t(i);
    names.push_back(scene.prototypes[i]->name);
  }
  reader.fail(
      path, fmt::format("no prototype named '{}' (prototypes: {})", name, fmt::join(names, ", ")));
}

void readPrototypes(const JsonReader& reader, const Json& value, const std::string& base_dir,
                    const std::vector<MeshArrays>& arrays, Scene& scene) {
  reader.expectArray(value, "prototypes");
  std::set<std::string> names;
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string path = JsonReader::element("prototypes", i);
    Mesh mesh = readMeshValue(reader, value[i], path, base_dir, arrays, scene);
    if (!names.insert(mesh.name).second) {
      reader.fail(path, fmt::format("prototype '{}' is defined twice (give each a distinct "
                                    "\"name\")",
                                    mesh.name));
    }
    scene.prototypes.push_back(std::make_shared<const Mesh>(std::move(mesh)));
  }
}

void readInstance(const JsonReader& reader, const Json& entry, const std::string& path,
                  Scene& scene) {
  reader.expectObject(entry, path, {"prototype", "transform", "matrix", "material", "name"});
  MeshInstance instance;
  instance.prototype = readPrototypeRef(reader, reader.required(entry, path, "prototype"),
                                        JsonReader::child(path, "prototype"), scene);
  const Json* transform = JsonReader::find(entry, "transform");
  const Json* matrix = JsonReader::find(entry, "matrix");
  if (transform && matrix) {
    reader.fail(path, "takes \"transform\" or \"matrix\", not both");
  }
  if (transform) {
    instance.transform =
        readTransformValue(reader, *transform, JsonReader::child(path, "transform"));
  }
  if (matrix) instance.transform = readMatrix(reader, *matrix, JsonReader::child(path, "matrix"));
  const mat3 linear(instance.transform);
  if (glm::determinant(glm::dmat3(linear)) == 0.0) {
    reader.fail(JsonReader::child(path, matrix ? "matrix" : "transform"),
                "is singular (it flattens the prototype)");
  }
  instance.material = scene.prototypes[instance.prototype]->material;
  if (const Json* material = JsonReader::find(entry, "material")) {
    instance.material =
        readMaterialValue(reader, *material, JsonReader::child(path, "material"), scene);
  }
  if (const Json* name = JsonReader::find(entry, "name")) {
    instance.name = reader.string(*name, JsonReader::child(path, "name"));
  }
  scene.instances.push_back(std::move(instance));
}

}  // namespace

void readPrototypesAndInstances(const JsonReader& reader, const Json* prototypes,
                                const Json* instances, const std::string& base_dir,
                                const std::vector<MeshArrays>& arrays, Scene& scene) {
  if (prototypes) readPrototypes(reader, *prototypes, base_dir, arrays, scene);
  if (!instances) return;
  reader.expectArray(*instances, "instances");
  for (size_t i = 0; i < instances->size(); ++i) {
    readInstance(reader, (*instances)[i], JsonReader::element("instances", i), scene);
  }
}

}  // namespace penumbra
