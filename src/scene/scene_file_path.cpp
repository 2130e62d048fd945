// The "path" of a scene file: keyframes for the camera and lights (path.h).
#include "core/error.h"
#include "scene/scene_file_impl.h"

namespace penumbra {

namespace {

float readKeyTime(const JsonReader& reader, const Json& key, const std::string& path,
                  float previous, size_t index) {
  const float time =
      reader.number(reader.required(key, path, "time"), JsonReader::child(path, "time"));
  if (index > 0 && !(time > previous)) {
    reader.fail(
        JsonReader::child(path, "time"),
        fmt::format("{} must be greater than the previous key's time ({})", time, previous));
  }
  return time;
}

std::vector<CameraKey> readCameraKeys(const JsonReader& reader, const Json& value,
                                      const std::string& path, const Camera& camera) {
  reader.expectArray(value, path);
  if (value.empty()) reader.fail(path, "needs at least one key");
  std::vector<CameraKey> keys;
  for (size_t k = 0; k < value.size(); ++k) {
    const std::string key_path = JsonReader::element(path, k);
    reader.expectObject(value[k], key_path, {"time", "position", "target", "fov"});
    CameraKey key;
    key.time = readKeyTime(reader, value[k], key_path, keys.empty() ? 0.0f : keys.back().time, k);
    key.position = reader.vector3(reader.required(value[k], key_path, "position"),
                                  JsonReader::child(key_path, "position"));
    key.target = reader.vector3(reader.required(value[k], key_path, "target"),
                                JsonReader::child(key_path, "target"));
    if (key.position == key.target) reader.fail(key_path, "position and target must differ");
    key.fov_y = reader.number(value[k], key_path, "fov", camera.fov_y);
    if (!(key.fov_y > 0.0f && key.fov_y < 180.0f)) {
      reader.fail(JsonReader::child(key_path, "fov"),
                  fmt::format("must be in (0, 180) degrees (got {})", key.fov_y));
    }
    keys.push_back(key);
  }
  return keys;
}

LightPath readLightPath(const JsonReader& reader, const Json& value, const std::string& path,
                        const Scene& scene) {
  reader.expectObject(value, path, {"light", "keys"});
  LightPath light;
  const std::string index_path = JsonReader::child(path, "light");
  const int index = reader.integer(value, path, "light", 0);
  if (index < 0 || size_t(index) >= scene.lights.size()) {
    reader.fail(index_path, fmt::format("light {} is out of range (the scene has {} lights)", index,
                                        scene.lights.size()));
  }
  light.light = uint32_t(index);
  const std::string keys_path = JsonReader::child(path, "keys");
  const Json& keys = reader.required(value, path, "keys");
  reader.expectArray(keys, keys_path);
  if (keys.empty()) reader.fail(keys_path, "needs at least one key");
  for (size_t k = 0; k < keys.size(); ++k) {
    const std::string key_path = JsonReader::element(keys_path, k);
    reader.expectObject(keys[k], key_path, {"time", "center"});
    LightKey key;
    key.time = readKeyTime(reader, keys[k], key_path,
                           light.keys.empty() ? 0.0f : light.keys.back().time, k);
    key.center = reader.vector3(reader.required(keys[k], key_path, "center"),
                                JsonReader::child(key_path, "center"));
    light.keys.push_back(key);
  }
  return light;
}

}  // namespace

void readScenePath(const JsonReader& reader, const Json& value, Scene& scene) {
  reader.expectObject(value, "path", {"frames", "camera", "lights"});
  ScenePath path;
  path.frames = reader.integer(reader.required(value, "path", "frames"), "path.frames");
  if (path.frames < 1 || path.frames > 1000000) {
    reader.fail("path.frames", fmt::format("must be in 1..1000000 (got {})", path.frames));
  }
  if (const Json* camera = JsonReader::find(value, "camera")) {
    path.camera = readCameraKeys(reader, *camera, "path.camera", scene.camera);
  }
  if (const Json* lights = JsonReader::find(value, "lights")) {
    reader.expectArray(*lights, "path.lights");
    for (size_t i = 0; i < lights->size(); ++i) {
      path.lights.push_back(
          readLightPath(reader, (*lights)[i], JsonReader::element("path.lights", i), scene));
    }
  }
  if (path.camera.empty() && path.lights.empty()) {
    reader.fail("path",
                "moves neither the camera nor a light (give \"camera\" or \"lights\" keys)");
  }
  scene.path = std::move(path);
}

}  // namespace penumbra
