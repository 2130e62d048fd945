#pragma once
// Strict, typed reading of a JSON document for scene files: every accessor names the key path
// ("lights[0].radius") and the document in its error, unknown keys are errors (they are usually
// typos), and numbers must be finite. Wraps nlohmann::json.
#include <vector>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/math.h"

namespace penumbra {

using Json = nlohmann::json;

class JsonReader {
 public:
  explicit JsonReader(std::string origin) : origin_(std::move(origin)) {}

  // Parses text (// and /* */ comments allowed); throws penumbra::Error "origin: invalid JSON:
  // ..." with line and column, also for a key repeated within one object (nlohmann would keep
  // only the last).
  Json parse(const std::string& text) const;

  // Throws "origin: path: what".
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  const std::string& origin() const { return origin_; }

  // Checks `value` is an object whose keys are all in `allowed`.
  void expectObject(const Json& value, const std::string& path,
                    const std::vector<std::string_view>& allowed) const;
  void expectArray(const Json& value, const std::string& path) const;

  // Member `key` of an object, or nullptr when absent.
  static const Json* find(const Json& object, const char* key);
  static std::string child(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }
  static std::string element(const std::string& path, size_t index) {
    return path + "[" + std::to_string(index) + "]";
  }

  float number(const Json& value, const std::string& path) const;
  int integer(const Json& value, const std::string& path) const;
  std::string string(const Json& value, const std::string& path) const;
  vec3 vector3(const Json& value, const std::string& path) const;

  // Optional members with defaults.
  float number(const Json& object, const std::string& path, const char* key, float fallback) const;
  int integer(const Json& object, const std::string& path, const char* key, int fallback) const;
  vec3 vector3(const Json& object, const std::string& path, const char* key, vec3 fallback) const;
  // Required member: "path.key: missing" when absent.
  const Json& required(const Json& object, const std::string& path, const char* key) const;

 private:
  std::string origin_;
};

}  // namespace penumbra
