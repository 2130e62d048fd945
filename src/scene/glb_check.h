#pragma once
// A check of a binary glTF (GLB) container's lengths before assimp reads it: assimp 5.2 trusts
// the JSON chunk's length and allocates it (a 588-byte file claiming a 2 GB chunk allocates
// 2 GB, then fails with a message about something else).
#include <string>
#include <string_view>

namespace penumbra {

// Throws penumbra::Error "<path>: ..." when the GLB header's total length or a chunk's length
// does not fit in `bytes` (the whole file). glTF 1.0's binary header (a scene length instead of
// chunks) is checked the same way.
void checkGlbBytes(const std::string& path, std::string_view bytes);

// A text glTF (.gltf) must be a JSON object with an "asset" object before assimp reads it: on
// other bytes assimp 5.2 falls back to guessing the format from words in the file, and one
// such guess loops forever on a 24-byte file a fuzzer found (fuzz/corpus/gltf/). Throws
// penumbra::Error "<path>: not a glTF file: ..." naming the JSON error's line and column.
void checkGltfText(const std::string& path, std::string_view bytes);

}  // namespace penumbra
