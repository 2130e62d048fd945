#include "scene/scene_file.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/image_io.h"
#include "scene/builtin_scenes.h"
#include "scene/flatten_instances.h"
#include "scene/scene_builder.h"
#include "scene/scene_file_impl.h"

namespace penumbra {

namespace {

namespace fs = std::filesystem;

void checkNonNegative(const JsonReader& reader, const vec3& v, const std::string& path) {
  if (v.x < 0.0f || v.y < 0.0f || v.z < 0.0f) reader.fail(path, "components must be >= 0");
}

void readMaterials(const JsonReader& reader, const Json& value, Scene& scene) {
  reader.expectArray(value, "materials");
  std::set<std::string> names;
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string path = JsonReader::element("materials", i);
    const Json& entry = value[i];
    reader.expectObject(entry, path, {"name", "albedo", "specular", "shininess"});
    Material m;
    m.name = entry.contains("name") ? reader.string(entry["name"], JsonReader::child(path, "name"))
                                    : "material" + std::to_string(i);
    if (!names.insert(m.name).second) {
      reader.fail(JsonReader::child(path, "name"),
                  fmt::format("material '{}' is defined twice", m.name));
    }
    m.albedo = reader.vector3(entry, path, "albedo", m.albedo);
    checkNonNegative(reader, m.albedo, JsonReader::child(path, "albedo"));
    m.specular = reader.vector3(entry, path, "specular", m.specular);
    checkNonNegative(reader, m.specular, JsonReader::child(path, "specular"));
    m.shininess = reader.number(entry, path, "shininess", m.shininess);
    if (m.shininess < 0.0f) reader.fail(JsonReader::child(path, "shininess"), "must be >= 0");
    scene.materials.push_back(m);
  }
}

// A light radius beyond this many times the scene's size is refused: no technique can use it
// (penumbra wedges need a radius below the distance to every silhouette edge, and the oracle's
// samples of a sphere that size lose all precision at the scene), so it is a typo or a fuzzer's
// number. A far, large light (a sun) stays within it: its distance counts in the scene's size.
constexpr double kMaxLightRadiusOverScene = 1000.0;

void checkLightRadius(const JsonReader& reader, const Scene& scene, const Light& light,
                      const std::string& path) {
  Bounds3 bounds;
  for (const Mesh& mesh : scene.meshes) bounds.extend(mesh.bounds());
  bounds.extend(light.center);
  const double size = glm::length(dvec3(bounds.extent()));
  const double limit = kMaxLightRadiusOverScene * size;
  if (size > 0.0 && double(light.radius) > limit) {
    reader.fail(path, fmt::format("{} is larger than the scene by orders of magnitude (the meshes "
                                  "and the light centre fit in a box {:.6g} across); at most "
                                  "{:.6g} ({} times that) is accepted",
                                  light.radius, size, limit, kMaxLightRadiusOverScene));
  }
}

// "shape": "sphere" (default), "disk" with a "normal", or "rectangle" with edge vectors "u"
// and "v" (its size: a rectangle takes no "radius"). Keys of another shape are refused, so a
// forgotten "shape" does not silently make a sphere of a rectangle.
void readLightShape(const JsonReader& reader, const Json& entry, const std::string& path,
                    Light& light) {
  const std::string shape_path = JsonReader::child(path, "shape");
  const std::string shape =
      entry.contains("shape") ? reader.string(entry["shape"], shape_path) : "sphere";
  const auto refuse = [&](const char* key, const char* why) {
    if (entry.contains(key)) reader.fail(JsonReader::child(path, key), why);
  };
  if (shape == "sphere") {
    refuse("normal", "only a disk light takes a normal (set \"shape\": \"disk\")");
    refuse("u", "only a rectangle light takes edges u and v (set \"shape\": \"rectangle\")");
    refuse("v", "only a rectangle light takes edges u and v (set \"shape\": \"rectangle\")");
    return;
  }
  if (shape == "disk") {
    refuse("u", "a disk light takes a radius and a normal, not edges u and v");
    refuse("v", "a disk light takes a radius and a normal, not edges u and v");
    const std::string normal_path = JsonReader::child(path, "normal");
    const vec3 normal = reader.vector3(reader.required(entry, path, "normal"), normal_path);
    const float length = glm::length(normal);
    if (!(length > 0.0f) || !std::isfinite(length)) {
      reader.fail(normal_path, "must be a non-zero finite vector");
    }
    light.shape = LightShape::Disk;
    light.normal = normal / length;
    return;
  }
  if (shape == "rectangle") {
    refuse("radius", "a rectangle light's size is its edges u and v; it takes no radius");
    refuse("normal", "a rectangle light's plane is that of its edges u and v; it takes no normal");
    const vec3 u = reader.vector3(reader.required(entry, path, "u"), JsonReader::child(path, "u"));
    const vec3 v = reader.vector3(reader.required(entry, path, "v"), JsonReader::child(path, "v"));
    const double lu = glm::length(dvec3(u)), lv = glm::length(dvec3(v));
    if (!(lu > 0.0) || !std::isfinite(lu)) {
      reader.fail(JsonReader::child(path, "u"), "must be a non-zero finite vector");
    }
    if (!(lv > 0.0) || !std::isfinite(lv)) {
      reader.fail(JsonReader::child(path, "v"), "must be a non-zero finite vector");
    }
    if (std::abs(glm::dot(dvec3(u), dvec3(v))) > 1e-4 * lu * lv) {
      reader.fail(JsonReader::child(path, "v"), "must be orthogonal to u (a rectangle's edges)");
    }
    const Light rectangle = rectangleLight(light.center, u, v);
    light.shape = rectangle.shape;
    light.edge_u = rectangle.edge_u;
    light.edge_v = rectangle.edge_v;
    light.radius = rectangle.radius;
    return;
  }
  reader.fail(shape_path,
              fmt::format("unknown light shape \"{}\" (sphere, disk or rectangle)", shape));
}

// A rectangle light's "texture": a PNG file (sRGB, decoded to linear RGB; relative to the scene
// file) or {"width": W, "height": H, "texels": [[r, g, b], ...]} in linear RGB, row 0 first
// (light.h gives the mapping onto the rectangle).
std::shared_ptr<const LightTexture> readLightTexture(const JsonReader& reader, const Json& value,
                                                     const std::string& path,
                                                     const std::string& base_dir) {
  if (value.is_string()) {
    const std::string file = resolveMeshPath(reader.string(value, path), base_dir);
    Image<vec3> image;
    try {
      image = readPng(file);
    } catch (const Error& e) {
      reader.fail(path, e.what());
    }
    std::vector<vec3> texels(image.data(), image.data() + image.size());
    try {
      return makeLightTexture(image.width(), image.height(), texels, file);
    } catch (const Error& e) {
      reader.fail(path, e.what());
    }
  }
  reader.expectObject(value, path, {"width", "height", "texels"});
  const int width =
      reader.integer(reader.required(value, path, "width"), JsonReader::child(path, "width"));
  const int height =
      reader.integer(reader.required(value, path, "height"), JsonReader::child(path, "height"));
  if (width < 1 || width > 4096 || height < 1 || height > 4096) {
    reader.fail(path,
                fmt::format("width and height must be in 1..4096 (got {}x{})", width, height));
  }
  const std::string texels_path = JsonReader::child(path, "texels");
  const Json& list = reader.required(value, path, "texels");
  reader.expectArray(list, texels_path);
  if (list.size() != size_t(width) * size_t(height)) {
    reader.fail(texels_path, fmt::format("holds {} texels, width x height is {}", list.size(),
                                         size_t(width) * size_t(height)));
  }
  std::vector<vec3> texels;
  texels.reserve(list.size());
  for (size_t k = 0; k < list.size(); ++k) {
    const std::string texel_path = JsonReader::element(texels_path, k);
    texels.push_back(reader.vector3(list[k], texel_path));
    checkNonNegative(reader, texels.back(), texel_path);
  }
  try {
    return makeLightTexture(width, height, texels, reader.origin());
  } catch (const Error& e) {
    reader.fail(path, e.what());
  }
}

void readLights(const JsonReader& reader, const Json& value, Scene& scene,
                const std::string& base_dir) {
  reader.expectArray(value, "lights");
  if (value.empty()) reader.fail("lights", "needs at least one light");
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string path = JsonReader::element("lights", i);
    const Json& entry = value[i];
    reader.expectObject(entry, path,
                        {"center", "radius", "color", "intensity", "shape", "normal", "u", "v",
                         "texture"});
    Light light;
    light.center =
        reader.vector3(reader.required(entry, path, "center"), JsonReader::child(path, "center"));
    readLightShape(reader, entry, path, light);
    light.radius = light.shape == LightShape::Rectangle
                       ? light.radius
                       : reader.number(entry, path, "radius", 0.0f);
    if (light.radius < 0.0f) {
      reader.fail(JsonReader::child(path, "radius"),
                  fmt::format("must be >= 0 (got {})", light.radius));
    }
    checkLightRadius(reader, scene, light, JsonReader::child(path, "radius"));
    light.color = reader.vector3(entry, path, "color", light.color);
    checkNonNegative(reader, light.color, JsonReader::child(path, "color"));
    light.intensity = reader.number(entry, path, "intensity", light.intensity);
    if (light.intensity < 0.0f) {
      reader.fail(JsonReader::child(path, "intensity"),
                  fmt::format("must be >= 0 (got {})", light.intensity));
    }
    if (entry.contains("texture")) {
      const std::string texture_path = JsonReader::child(path, "texture");
      if (light.shape != LightShape::Rectangle) {
        reader.fail(texture_path, "only a rectangle light takes a texture (set \"shape\": "
                                  "\"rectangle\")");
      }
      light.texture = readLightTexture(reader, entry["texture"], texture_path, base_dir);
    }
    scene.lights.push_back(light);
  }
}

void readSettings(const JsonReader& reader, const Json& value, RenderSettings& settings) {
  reader.expectObject(value, "settings", {"width", "height", "ambient", "background"});
  for (const char* key : {"width", "height"}) {
    int& size = key[0] == 'w' ? settings.width : settings.height;
    size = reader.integer(value, "settings", key, size);
    if (size < 1 || size > 8192) {
      reader.fail(JsonReader::child("settings", key),
                  fmt::format("must be in 1..8192 (got {})", size));
    }
  }
  settings.ambient = reader.vector3(value, "settings", "ambient", settings.ambient);
  checkNonNegative(reader, settings.ambient, "settings.ambient");
  settings.background = reader.vector3(value, "settings", "background", settings.background);
  checkNonNegative(reader, settings.background, "settings.background");
}

void readCamera(const JsonReader& reader, const Json& value, Camera& camera) {
  reader.expectObject(value, "camera", {"position", "target", "up", "fov", "near"});
  camera.position = reader.vector3(reader.required(value, "camera", "position"), "camera.position");
  camera.target = reader.vector3(reader.required(value, "camera", "target"), "camera.target");
  camera.up = reader.vector3(value, "camera", "up", camera.up);
  camera.fov_y = reader.number(value, "camera", "fov", camera.fov_y);
  if (camera.fov_y <= 0.0f || camera.fov_y >= 180.0f) {
    reader.fail("camera.fov", fmt::format("must be in (0, 180) degrees (got {})", camera.fov_y));
  }
  camera.near_plane = reader.number(value, "camera", "near", camera.near_plane);
  if (camera.near_plane <= 0.0f) {
    reader.fail("camera.near", fmt::format("must be > 0 (got {})", camera.near_plane));
  }
}

// Scene files that name a base scene, nested: a file naming itself (directly or through
// others) would otherwise recurse until the stack runs out.
thread_local int base_depth = 0;
constexpr int kMaxBaseDepth = 32;

// A file with "base": the geometry, materials and settings of a built-in scene, a scene file or
// a mesh file (as `penumbra render` takes them; a relative path is relative to this file's
// folder), with this file's camera, lights and settings in place of the base's. The viewer
// saves what it shows this way (its camera and lights over the scene it opened).
Scene parseSceneOverBase(const JsonReader& reader, const Json& root, const Json& base_value,
                         const std::string& base_dir) {
  for (const char* key : {"meshes", "materials", "prototypes", "instances"}) {
    if (root.contains(key)) {
      reader.fail(key, "a scene with a \"base\" takes its meshes, materials, prototypes and "
                       "instances from the base");
    }
  }
  const std::string base = reader.string(base_value, "base");
  if (base.empty()) reader.fail("base", "must name a built-in scene, a scene file or a mesh file");
  const bool relative = !isBuiltinScene(base) && fs::path(base).is_relative();
  const std::string resolved = relative ? (fs::path(base_dir) / base).string() : base;
  if (base_depth >= kMaxBaseDepth) {
    reader.fail("base", fmt::format("bases nest more than {} deep (does a file name itself?)",
                                    kMaxBaseDepth));
  }
  Scene scene;
  ++base_depth;
  try {
    scene = loadScene(resolved);
  } catch (const Error& e) {
    --base_depth;
    reader.fail("base", e.what());
  }
  --base_depth;
  if (root.contains("name")) scene.name = reader.string(root["name"], "name");
  if (root.contains("description")) (void)reader.string(root["description"], "description");
  if (const Json* settings = JsonReader::find(root, "settings")) {
    readSettings(reader, *settings, scene.settings);
  }
  if (const Json* camera = JsonReader::find(root, "camera"))
    readCamera(reader, *camera, scene.camera);
  if (const Json* lights = JsonReader::find(root, "lights")) {
    scene.lights.clear();
    readLights(reader, *lights, scene, base_dir);
  }
  if (const Json* path = JsonReader::find(root, "path")) readScenePath(reader, *path, scene);
  try {
    scene.finalize();
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", reader.origin(), e.what()));
  }
  return scene;
}

}  // namespace

std::string modelsDirectory() {
  if (const char* env = std::getenv("PENUMBRA_MODELS"); env != nullptr && *env != '\0') return env;
  // The developers' shared folder beside the source tree wins when it exists; users have the
  // cache that scripts/fetch-models.sh fills.
  const fs::path shared = fs::path(PENUMBRA_DEFAULT_MODELS_DIR).lexically_normal();
  std::error_code ec;
  if (fs::is_directory(shared, ec)) return shared.string();
  return userModelsCache();
}

std::string userModelsCache() {
  // The XDG base directory specification: $XDG_CACHE_HOME, else ~/.cache.
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg == '/') {
    return (fs::path(xdg) / "penumbra" / "models").string();
  }
  const char* home = std::getenv("HOME");
  return (fs::path(home != nullptr && *home != '\0' ? home : ".") / ".cache" / "penumbra" /
          "models")
      .string();
}

std::string shippedModelsDirectory() {
  return fs::path(PENUMBRA_SHIPPED_MODELS_DIR).lexically_normal().string();
}

std::string modelPath(const std::string& name) {
  const fs::path in_models_folder = fs::path(modelsDirectory()) / name;
  std::error_code ec;
  if (fs::exists(in_models_folder, ec)) return in_models_folder.string();
  const fs::path shipped = fs::path(shippedModelsDirectory()) / name;
  if (fs::exists(shipped, ec)) return shipped.string();
  return in_models_folder.string();
}

Scene loadSceneFile(const std::string& path) {
  std::error_code ec;
  PENUMBRA_CHECK(fs::exists(path, ec), "{}: scene file not found", path);
  std::ifstream in(path, std::ios::binary);
  PENUMBRA_CHECK(in.good() && fs::is_regular_file(path, ec), "{}: cannot read the scene file",
                 path);
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = parseSceneJson(text.str(), path, fs::path(path).parent_path().string());
  return scene;
}

Scene parseSceneJson(const std::string& text, const std::string& origin,
                     const std::string& base_dir) {
  return parseSceneJson(text, origin, base_dir, {});
}

Scene parseSceneJson(const std::string& text, const std::string& origin,
                     const std::string& base_dir, const std::vector<MeshArrays>& arrays) {
  const JsonReader reader(origin);
  const Json root = reader.parse(text);
  if (!root.is_object()) reader.fail("", "the scene must be a JSON object");
  reader.expectObject(root, "", {"name", "description", "base", "camera", "lights", "materials",
                                 "meshes", "prototypes", "instances", "settings", "path"});
  if (const Json* base = JsonReader::find(root, "base")) {
    return parseSceneOverBase(reader, root, *base, base_dir);
  }

  Scene scene;
  scene.name = root.contains("name") ? reader.string(root["name"], "name")
                                     : fs::path(origin).stem().string();
  if (root.contains("description")) (void)reader.string(root["description"], "description");
  if (const Json* materials = JsonReader::find(root, "materials")) {
    readMaterials(reader, *materials, scene);
  }
  if (scene.materials.empty()) scene.materials.push_back(Material{});

  // "meshes" may be left out when "instances" place the geometry.
  const Json* instances = JsonReader::find(root, "instances");
  static const Json kNoMeshes = Json::array();
  const Json& meshes = instances && !root.contains("meshes") ? kNoMeshes
                                                             : reader.required(root, "", "meshes");
  reader.expectArray(meshes, "meshes");
  for (size_t i = 0; i < meshes.size(); ++i) {
    readMeshEntry(reader, meshes[i], JsonReader::element("meshes", i), base_dir, arrays, scene);
  }
  const Json* prototypes = JsonReader::find(root, "prototypes");
  if (prototypes && !instances)
    reader.fail("prototypes", "are given but no \"instances\" place them");
  readPrototypesAndInstances(reader, prototypes, instances, base_dir, arrays, scene);
  // Now, so that the lights' size check and the default camera see the instances.
  try {
    flattenInstances(scene);
  } catch (const Error& e) {
    reader.fail("instances", e.what());
  }
  readLights(reader, reader.required(root, "", "lights"), scene, base_dir);
  if (const Json* settings = JsonReader::find(root, "settings")) {
    readSettings(reader, *settings, scene.settings);
  }
  if (const Json* camera = JsonReader::find(root, "camera")) {
    readCamera(reader, *camera, scene.camera);
  } else if (scene.triangleCount() > 0) {
    // No camera: look at everything from the front, a little to the right and above.
    try {
      scene.camera = frameBounds(scene.bounds(), vec3(0.5f, 0.45f, 1.0f), scene.settings.width,
                                 scene.settings.height);
    } catch (const Error& e) {
      reader.fail("camera", fmt::format("not given, and {}", e.what()));
    }
  }
  if (const Json* path = JsonReader::find(root, "path")) readScenePath(reader, *path, scene);
  try {
    scene.finalize();
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", origin, e.what()));
  }
  return scene;
}

}  // namespace penumbra
