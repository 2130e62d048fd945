#pragma once
// A file name's extension in lower case, with its dot (".obj", ".PLY" -> ".ply"; "" for none):
// the loaders and image writers choose their format by it.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace penumbra {

inline std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace penumbra
