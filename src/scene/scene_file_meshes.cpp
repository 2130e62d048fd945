// The "meshes" entries of a scene file: mesh files and generators, materials, transforms.
#include <algorithm>
#include <filesystem>
#include <string_view>
#include <vector>

#include <fmt/ranges.h>

#include "core/error.h"
#include "scene/generators.h"
#include "scene/load_mesh.h"
#include "scene/mesh_ops.h"
#include "scene/scene_file.h"
#include "scene/scene_file_impl.h"
#include "scene/shapes.h"
#include "scene/teapot.h"
#include "scene/up_axis.h"

namespace penumbra {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kModelsPrefix = "models:";

using GeneratorFn = Mesh (*)(const JsonReader&, const Json&, const std::string&);

struct GeneratorSpec {
  std::string_view name;
  std::vector<std::string_view> keys;  // parameters besides the keys every entry may have
  GeneratorFn make;
};

// Parameters and defaults are documented in docs/scene-format.md.
const std::vector<GeneratorSpec>& generators() {
  static const std::vector<GeneratorSpec> kGenerators = {
      {"plane",
       {"center", "half_size"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeGroundPlane(r.vector3(e, p, "center", vec3(0.0f)),
                                r.number(e, p, "half_size", 10.0f));
       }},
      {"box",
       {"min", "max"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeBox(r.vector3(r.required(e, p, "min"), JsonReader::child(p, "min")),
                        r.vector3(r.required(e, p, "max"), JsonReader::child(p, "max")));
       }},
      {"sphere",
       {"center", "radius", "segments", "rings"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeSphere(r.vector3(e, p, "center", vec3(0.0f)), r.number(e, p, "radius", 1.0f),
                           r.integer(e, p, "segments", 32), r.integer(e, p, "rings", 16));
       }},
      {"cylinder",
       {"base", "radius", "height", "segments"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeCylinder(r.vector3(e, p, "base", vec3(0.0f)), r.number(e, p, "radius", 0.5f),
                             r.number(e, p, "height", 1.0f), r.integer(e, p, "segments", 24));
       }},
      {"disk",
       {"center", "normal", "radius", "segments"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeDisk(r.vector3(e, p, "center", vec3(0.0f)),
                         r.vector3(e, p, "normal", vec3(0.0f, 1.0f, 0.0f)),
                         r.number(e, p, "radius", 1.0f), r.integer(e, p, "segments", 64));
       }},
      {"fractal",
       {"level", "half_size", "roughness", "seed"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         const int seed = r.integer(e, p, "seed", 1);
         if (seed < 0) r.fail(JsonReader::child(p, "seed"), "must be >= 0");
         return makeFractalTerrain(r.integer(e, p, "level", 8), r.number(e, p, "half_size", 5.0f),
                                   r.number(e, p, "roughness", 0.5f), uint32_t(seed));
       }},
      {"torus",
       {"center", "major_radius", "minor_radius", "segments", "sides"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeTorus(r.vector3(e, p, "center", vec3(0.0f)),
                          r.number(e, p, "major_radius", 1.0f),
                          r.number(e, p, "minor_radius", 0.25f), r.integer(e, p, "segments", 48),
                          r.integer(e, p, "sides", 16));
       }},
      {"teapot",
       {"base", "height"},
       [](const JsonReader& r, const Json& e, const std::string& p) {
         return makeTeapot(r.vector3(e, p, "base", vec3(0.0f)), r.number(e, p, "height", 1.0f));
       }},
  };
  return kGenerators;
}

const std::vector<std::string_view> kCommonKeys = {"name", "material", "transform", "fit"};

mat4 readRotation(const JsonReader& reader, const Json& value, const std::string& path) {
  if (value.is_array()) {
    // Euler angles in degrees, applied about x first, then y, then z (fixed axes).
    const vec3 degrees = reader.vector3(value, path);
    mat4 r(1.0f);
    r = glm::rotate(r, glm::radians(degrees.z), vec3(0, 0, 1));
    r = glm::rotate(r, glm::radians(degrees.y), vec3(0, 1, 0));
    r = glm::rotate(r, glm::radians(degrees.x), vec3(1, 0, 0));
    return r;
  }
  reader.expectObject(value, path, {"axis", "degrees"});
  const vec3 axis =
      reader.vector3(reader.required(value, path, "axis"), JsonReader::child(path, "axis"));
  if (glm::length(axis) == 0.0f) reader.fail(JsonReader::child(path, "axis"), "must not be zero");
  const float degrees =
      reader.number(reader.required(value, path, "degrees"), JsonReader::child(path, "degrees"));
  return glm::rotate(mat4(1.0f), glm::radians(degrees), glm::normalize(axis));
}

// translate * rotate * scale: the mesh is scaled, then rotated, then moved.
mat4 readTransform(const JsonReader& reader, const Json& value, const std::string& path) {
  reader.expectObject(value, path, {"translate", "rotate", "scale"});
  vec3 scale(1.0f);
  if (const Json* s = JsonReader::find(value, "scale")) {
    const std::string scale_path = JsonReader::child(path, "scale");
    scale = s->is_number() ? vec3(reader.number(*s, scale_path)) : reader.vector3(*s, scale_path);
    if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) {
      reader.fail(scale_path, "must not be zero");
    }
  }
  mat4 rotation(1.0f);
  if (const Json* r = JsonReader::find(value, "rotate")) {
    rotation = readRotation(reader, *r, JsonReader::child(path, "rotate"));
  }
  const vec3 translate = reader.vector3(value, path, "translate", vec3(0.0f));
  return glm::translate(mat4(1.0f), translate) * rotation * glm::scale(mat4(1.0f), scale);
}

// Scales uniformly so the largest extent is `size`, centred on x = z = 0, bottom at y = 0.
mat4 fitTransform(const Mesh& mesh, float size) {
  const Bounds3 b = mesh.bounds();
  const vec3 extent = b.extent();
  const float largest = std::max({extent.x, extent.y, extent.z});
  const float s = largest > 0.0f ? size / largest : 1.0f;
  const vec3 c = b.center();
  return glm::scale(mat4(1.0f), vec3(s)) * glm::translate(mat4(1.0f), vec3(-c.x, -b.min.y, -c.z));
}

uint32_t readMaterialRef(const JsonReader& reader, const Json& value, const std::string& path,
                         const Scene& scene) {
  if (value.is_number_integer()) {
    const int index = reader.integer(value, path);
    if (index < 0 || size_t(index) >= scene.materials.size()) {
      reader.fail(path, fmt::format("material index {} is out of range (there are {} materials)",
                                    index, scene.materials.size()));
    }
    return uint32_t(index);
  }
  if (!value.is_string()) reader.fail(path, "expected a material name or index");
  const std::string name = value.get<std::string>();
  std::vector<std::string> names;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return uint32_t(i);
    names.push_back(scene.materials[i].name);
  }
  reader.fail(path,
              fmt::format("no material named '{}' (materials: {})", name, fmt::join(names, ", ")));
}

Mesh readFileMesh(const JsonReader& reader, const Json& entry, const std::string& path,
                  const std::string& base_dir) {
  std::vector<std::string_view> keys = kCommonKeys;
  keys.push_back("file");
  keys.push_back("up");
  reader.expectObject(entry, path, keys);
  const std::string file_path = JsonReader::child(path, "file");
  const std::string file = reader.string(entry["file"], file_path);
  if (file.starts_with(kModelsPrefix) && !isInsideModelsFolder(file)) {
    reader.fail(file_path, fmt::format("{} is not a name inside the models folder (no '..', no "
                                       "absolute path)",
                                       file));
  }
  const std::string resolved = resolveMeshPath(file, base_dir);
  std::error_code ec;
  if (file.starts_with(kModelsPrefix) && !fs::exists(resolved, ec)) {
    reader.fail(file_path, fmt::format("{} is not in the models folder {} nor in {} (run "
                                       "scripts/fetch-models.sh, or set PENUMBRA_MODELS to a "
                                       "folder holding it; 'penumbra scenes' lists what is "
                                       "missing)",
                                       file, modelsDirectory(), shippedModelsDirectory()));
  }
  UpAxis up = UpAxis::Y;
  if (const Json* value = JsonReader::find(entry, "up")) {
    const std::string up_path = JsonReader::child(path, "up");
    try {
      up = parseUpAxis(reader.string(*value, up_path));
    } catch (const Error& e) {
      if (std::string(e.what()).starts_with(reader.origin() + ":")) throw;
      reader.fail(up_path, e.what());
    }
  }
  try {
    Mesh mesh = loadMesh(resolved);
    // Stood up first, so that "fit" and "transform" work on the y-up mesh.
    if (up != UpAxis::Y) transformMesh(mesh, upAxisToY(up));
    return mesh;
  } catch (const Error& e) {
    reader.fail(file_path, e.what());
  }
}

// {"arrays": i}: the program's in-memory mesh arrays[i] (scene_file.h).
Mesh readArraysMesh(const JsonReader& reader, const Json& entry, const std::string& path,
                    const std::vector<MeshArrays>& arrays) {
  std::vector<std::string_view> keys = kCommonKeys;
  keys.push_back("arrays");
  reader.expectObject(entry, path, keys);
  const std::string arrays_path = JsonReader::child(path, "arrays");
  if (arrays.empty()) {
    reader.fail(arrays_path, "names in-memory mesh arrays, which only a program gives (a scene "
                             "file's meshes are \"file\" or \"generator\" entries)");
  }
  const int index = reader.integer(entry["arrays"], arrays_path);
  if (index < 0 || size_t(index) >= arrays.size()) {
    reader.fail(arrays_path, fmt::format("{} is out of range: {} mesh arrays were given", index,
                                         arrays.size()));
  }
  const Json* name = JsonReader::find(entry, "name");
  const std::string mesh_name = name ? reader.string(*name, JsonReader::child(path, "name"))
                                     : fmt::format("arrays {}", index);
  try {
    return meshFromArrays(arrays[size_t(index)], mesh_name);
  } catch (const Error& e) {
    reader.fail(path, e.what());
  }
}

Mesh readGeneratorMesh(const JsonReader& reader, const Json& entry, const std::string& path) {
  const std::string generator_path = JsonReader::child(path, "generator");
  const std::string kind = reader.string(entry["generator"], generator_path);
  std::vector<std::string_view> names;
  for (const GeneratorSpec& spec : generators()) {
    names.push_back(spec.name);
    if (spec.name != kind) continue;
    std::vector<std::string_view> keys = kCommonKeys;
    keys.push_back("generator");
    keys.insert(keys.end(), spec.keys.begin(), spec.keys.end());
    reader.expectObject(entry, path, keys);
    try {
      return spec.make(reader, entry, path);
    } catch (const Error& e) {
      // Generator parameter checks name the generator, not the key path: add the path.
      const std::string message = e.what();
      if (message.starts_with(reader.origin() + ":")) throw;
      reader.fail(path, message);
    }
  }
  reader.fail(generator_path,
              fmt::format("unknown generator '{}' (generators: {})", kind, fmt::join(names, ", ")));
}

}  // namespace

bool isInsideModelsFolder(const std::string& file) {
  if (!file.starts_with(kModelsPrefix)) return true;
  const fs::path name = fs::path(file.substr(kModelsPrefix.size())).lexically_normal();
  if (name.empty() || name.is_absolute() || name.has_root_name()) return false;
  for (const fs::path& part : name) {
    if (part == "..") return false;
  }
  return true;
}

std::string resolveMeshPath(const std::string& file, const std::string& base_dir) {
  if (file.starts_with(kModelsPrefix)) {
    return modelPath(file.substr(kModelsPrefix.size()));
  }
  fs::path p(file);
  if (p.is_relative() && !base_dir.empty()) p = fs::path(base_dir) / p;
  return p.lexically_normal().string();
}

mat4 readTransformValue(const JsonReader& reader, const Json& value, const std::string& path) {
  return readTransform(reader, value, path);
}

uint32_t readMaterialValue(const JsonReader& reader, const Json& value, const std::string& path,
                           const Scene& scene) {
  return readMaterialRef(reader, value, path, scene);
}

void readMeshEntry(const JsonReader& reader, const Json& entry, const std::string& path,
                   const std::string& base_dir, const std::vector<MeshArrays>& arrays,
                   Scene& scene) {
  scene.meshes.push_back(readMeshValue(reader, entry, path, base_dir, arrays, scene));
}

Mesh readMeshValue(const JsonReader& reader, const Json& entry, const std::string& path,
                   const std::string& base_dir, const std::vector<MeshArrays>& arrays,
                   const Scene& scene) {
  if (!entry.is_object()) reader.fail(path, "expected an object");
  const bool has_file = entry.contains("file");
  const bool has_generator = entry.contains("generator");
  const bool has_arrays = entry.contains("arrays");
  if (int(has_file) + int(has_generator) + int(has_arrays) != 1) {
    reader.fail(path, arrays.empty()
                          ? "needs exactly one of \"file\" (a mesh file) or \"generator\""
                          : "needs exactly one of \"file\" (a mesh file), \"generator\" or "
                            "\"arrays\" (mesh arrays given in memory)");
  }
  Mesh mesh = has_file        ? readFileMesh(reader, entry, path, base_dir)
              : has_generator ? readGeneratorMesh(reader, entry, path)
                              : readArraysMesh(reader, entry, path, arrays);

  mat4 transform(1.0f);
  const Json* fit = JsonReader::find(entry, "fit");
  if (fit) {
    const float size = reader.number(*fit, JsonReader::child(path, "fit"));
    if (size <= 0.0f) reader.fail(JsonReader::child(path, "fit"), "must be > 0");
    transform = fitTransform(mesh, size);
  }
  const Json* t = JsonReader::find(entry, "transform");
  if (t) {
    transform = readTransform(reader, *t, JsonReader::child(path, "transform")) * transform;
  }
  if (transform != mat4(1.0f)) {
    try {
      transformMesh(mesh, transform);
    } catch (const Error& e) {
      // Name the key that asked for the transform (a scale that overflows float, a fit of a
      // mesh with no extent).
      reader.fail(JsonReader::child(path, t ? "transform" : "fit"),
                  fit && t ? fmt::format("{} (with \"fit\")", e.what()) : std::string(e.what()));
    }
  }
  if (const Json* name = JsonReader::find(entry, "name")) {
    mesh.name = reader.string(*name, JsonReader::child(path, "name"));
  }
  mesh.material = 0;
  if (const Json* material = JsonReader::find(entry, "material")) {
    mesh.material = readMaterialRef(reader, *material, JsonReader::child(path, "material"), scene);
  }
  return mesh;
}

}  // namespace penumbra
