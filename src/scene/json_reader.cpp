#include "scene/json_reader.h"

#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include <fmt/ranges.h>

#include "core/error.h"

namespace penumbra {

Json JsonReader::parse(const std::string& text) const {
  // One set of keys per open object, to catch a key given twice in the same object.
  std::vector<std::set<std::string>> open_objects;
  auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start: open_objects.emplace_back(); break;
      case Json::parse_event_t::object_end: open_objects.pop_back(); break;
      case Json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        if (!open_objects.back().insert(key).second) {
          throw Error(fmt::format("{}: key '{}' appears twice in one object", origin_, key));
        }
        break;
      }
      default: break;
    }
    return true;
  };
  try {
    return Json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const Json::exception& e) {
    // e.what() starts with "[json.exception.parse_error.101] "; keep only the readable part.
    std::string what = e.what();
    if (const size_t end = what.find("] "); what.starts_with("[json.") && end != std::string::npos) {
      what = what.substr(end + 2);
    }
    throw Error(fmt::format("{}: invalid JSON: {}", origin_, what));
  }
}

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw Error(path.empty() ? fmt::format("{}: {}", origin_, what)
                           : fmt::format("{}: {}: {}", origin_, path, what));
}

void JsonReader::expectObject(const Json& value, const std::string& path,
                              const std::vector<std::string_view>& allowed) const {
  if (!value.is_object()) fail(path, "expected an object");
  for (const auto& [key, member] : value.items()) {
    bool known = false;
    for (std::string_view name : allowed) known |= name == key;
    if (!known) {
      fail(child(path, key.c_str()),
           fmt::format("unknown key (expected one of: {})", fmt::join(allowed, ", ")));
    }
  }
}

void JsonReader::expectArray(const Json& value, const std::string& path) const {
  if (!value.is_array()) fail(path, "expected an array");
}

const Json* JsonReader::find(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

float JsonReader::number(const Json& value, const std::string& path) const {
  if (!value.is_number()) fail(path, "expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x) || std::abs(x) > double(std::numeric_limits<float>::max())) {
    fail(path, fmt::format("{} is out of range", x));
  }
  return float(x);
}

int JsonReader::integer(const Json& value, const std::string& path) const {
  if (!value.is_number_integer()) fail(path, "expected an integer");
  const auto x = value.get<int64_t>();
  if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max()) {
    fail(path, fmt::format("{} is out of range", x));
  }
  return int(x);
}

std::string JsonReader::string(const Json& value, const std::string& path) const {
  if (!value.is_string()) fail(path, "expected a string");
  std::string text = value.get<std::string>();
  // A NUL would cut every message (and path) that quotes the string at that character.
  if (text.find('\0') != std::string::npos) {
    fail(path, "the string contains a NUL character (\\u0000)");
  }
  return text;
}

vec3 JsonReader::vector3(const Json& value, const std::string& path) const {
  if (!value.is_array() || value.size() != 3) fail(path, "expected an array of 3 numbers");
  return vec3(number(value[0], element(path, 0)), number(value[1], element(path, 1)),
              number(value[2], element(path, 2)));
}

float JsonReader::number(const Json& object, const std::string& path, const char* key,
                         float fallback) const {
  const Json* value = find(object, key);
  return value ? number(*value, child(path, key)) : fallback;
}

int JsonReader::integer(const Json& object, const std::string& path, const char* key,
                        int fallback) const {
  const Json* value = find(object, key);
  return value ? integer(*value, child(path, key)) : fallback;
}

vec3 JsonReader::vector3(const Json& object, const std::string& path, const char* key,
                         vec3 fallback) const {
  const Json* value = find(object, key);
  return value ? vector3(*value, child(path, key)) : fallback;
}

const Json& JsonReader::required(const Json& object, const std::string& path,
                                 const char* key) const {
  const Json* value = find(object, key);
  if (!value) fail(child(path, key), "missing");
  return *value;
}

}  // namespace penumbra
