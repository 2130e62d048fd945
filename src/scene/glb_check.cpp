#include "scene/glb_check.h"

#include "scene/json_reader.h"

#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace penumbra {
namespace {

// GLB integers are little-endian (glTF 2.0 specification, section 4.4.3).
uint32_t readU32(std::string_view bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(bytes[at + size_t(i)]);
  return v;
}

}  // namespace

void checkGlbBytes(const std::string& path, std::string_view bytes) {
  constexpr size_t kHeader = 12;
  PENUMBRA_CHECK(bytes.size() >= kHeader && bytes.substr(0, 4) == "glTF",
                 "{}: invalid GLB: the file does not start with a 12-byte 'glTF' header", path);
  const uint32_t version = readU32(bytes, 4);
  const uint32_t length = readU32(bytes, 8);
  PENUMBRA_CHECK(length <= bytes.size(),
                 "{}: invalid GLB: the header says {} bytes, the file has {}", path, length,
                 bytes.size());
  if (version == 1) {
    // glTF 1.0 binary: uint32 scene length, uint32 scene format, then the JSON scene.
    PENUMBRA_CHECK(bytes.size() >= 20, "{}: invalid GLB: the version 1 header is cut off", path);
    const uint64_t scene_length = readU32(bytes, 12);
    PENUMBRA_CHECK(20 + scene_length <= length,
                   "{}: invalid GLB: the scene is {} bytes, only {} follow the header", path,
                   scene_length, length - 20);
    return;
  }
  PENUMBRA_CHECK(version == 2, "{}: invalid GLB: version {} (1 and 2 are read)", path, version);
  // Chunks: uint32 length, uint32 type, then the data; the first is the JSON.
  size_t at = kHeader;
  int chunk = 0;
  PENUMBRA_CHECK(length >= kHeader + 8, "{}: invalid GLB: no JSON chunk", path);
  while (at < length) {
    PENUMBRA_CHECK(length - at >= 8, "{}: invalid GLB: chunk {}'s header is cut off", path, chunk);
    const uint64_t chunk_length = readU32(bytes, at);
    PENUMBRA_CHECK(chunk_length <= length - at - 8,
                   "{}: invalid GLB: chunk {} says {} bytes, only {} follow its header", path,
                   chunk, chunk_length, length - at - 8);
    at += 8 + size_t(chunk_length);
    ++chunk;
  }
}

void checkGltfText(const std::string& path, std::string_view bytes) {
  const JsonReader reader(path + ": not a glTF file");
  const Json root = reader.parse(std::string(bytes));
  if (!root.is_object()) reader.fail("", "the top level is not a JSON object");
  const Json* asset = JsonReader::find(root, "asset");
  if (asset == nullptr || !asset->is_object()) {
    reader.fail("asset", "missing (every glTF names its version in an \"asset\" object)");
  }
}

}  // namespace penumbra
