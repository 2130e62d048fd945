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

}  // namespace penumbra
