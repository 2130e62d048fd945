// libFuzzer target: loadMesh on arbitrary bytes saved with the extension PENUMBRA_FUZZ_EXTENSION
// (".obj", ".ply", ".gltf"), since assimp picks its reader by extension and content; glTF
// inputs that start with the binary magic "glTF" are saved as ".glb". A
// penumbra::Error is the right answer to bad bytes; any other exception, a crash, a sanitizer
// report, a hang (-timeout) or runaway memory (-rss_limit_mb) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.h"
#include "scene/load_mesh.h"

namespace {

// One file per fuzzing process, rewritten for every input.
std::string scratchPath(const uint8_t* data, size_t size) {
  static const std::string stem = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/penumbra-fuzz-" + std::to_string(::getpid());
  }();
  const std::string extension = PENUMBRA_FUZZ_EXTENSION;
  if (extension == ".gltf" && size >= 4 && std::memcmp(data, "glTF", 4) == 0) return stem + ".glb";
  return stem + extension;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = scratchPath(data, size);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  const bool written = std::fwrite(data, 1, size, f) == size;
  if (std::fclose(f) != 0 || !written) return 0;
  try {
    const penumbra::Mesh mesh = penumbra::loadMesh(path);
    // A loaded mesh is consistent: every index names a vertex.
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.positions.size()) __builtin_trap();
    }
  } catch (const penumbra::Error&) {
  }
  return 0;
}
