#pragma once
// What a PLY file's header declares, read before the file goes to assimp so that the file can
// be held against its own declaration, and what assimp returns against both (load_checks.h).
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

struct PlyElement {
  std::string name;    // "vertex", "face", "tristrips", ...
  uint64_t count = 0;
};

struct PlyHeader {
  bool is_ply = false;  // starts with "ply" and has a readable header up to "end_header"
  std::vector<PlyElement> elements;  // in header order
};

// Reads the header. is_ply is false when the file does not start with "ply" or its header
// cannot be read as one. (The body is held against the header before assimp reads it:
// ply_check.h.)
PlyHeader readPlyHeader(const std::string& path);

}  // namespace penumbra
