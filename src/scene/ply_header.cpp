#include "scene/ply_header.h"

#include <charconv>
#include <fstream>
#include <sstream>

namespace penumbra {

PlyHeader readPlyHeader(const std::string& path) {
  PlyHeader header;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) return header;
  // A real header is a few hundred bytes; the bound keeps a file without "end_header" from
  // being scanned whole.
  constexpr int kMaxHeaderLines = 10000;
  for (int n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword, first, second;
    words >> keyword >> first >> second;
    if (keyword == "end_header") {
      header.is_ply = true;
      break;
    }
    if (keyword != "element") continue;
    PlyElement element;
    element.name = first;
    const auto [end, ec] =
        std::from_chars(second.data(), second.data() + second.size(), element.count);
    if (first.empty() || ec != std::errc() || end != second.data() + second.size()) return {};
    header.elements.push_back(element);
  }
  if (!header.is_ply) return {};
  return header;
}

}  // namespace penumbra
