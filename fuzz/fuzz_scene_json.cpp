// libFuzzer target: the scene-file reader (JSON, generators, transforms, camera, lights) on
// arbitrary text. Mesh files it names are looked up in an empty folder, so the fuzzer explores
// the reader, not the disk. A penumbra::Error is the right answer; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string empty_dir = [] {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "penumbra-fuzz-empty";
    std::filesystem::create_directories(dir);
    setenv("PENUMBRA_MODELS", dir.c_str(), 1);
    return dir.string();
  }();
  try {
    (void)penumbra::parseSceneJson(std::string(reinterpret_cast<const char*>(data), size),
                                   "fuzz.json", empty_dir);
  } catch (const penumbra::Error&) {
  }
  return 0;
}
