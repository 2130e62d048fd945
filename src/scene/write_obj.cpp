#include "scene/write_obj.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra {

void writeObj(const std::string& path, const Mesh& mesh, const std::vector<std::string>& comments) {
  std::string text;
  for (const std::string& comment : comments) text += fmt::format("# {}\n", comment);
  // fmt's "{}" prints a float as the shortest decimal that round-trips (Ryu / Dragonbox).
  for (const vec3& p : mesh.positions) text += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    text += fmt::format("f {} {} {}\n", mesh.indices[i] + 1, mesh.indices[i + 1] + 1,
                        mesh.indices[i + 2] + 1);
  }
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen(partial.c_str(), "wb");
  PENUMBRA_CHECK(file != nullptr, "{}: cannot create the file", partial);
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const bool closed = std::fclose(file) == 0;
  std::error_code ec;
  if (!written || !closed) {
    std::filesystem::remove(partial, ec);
    throw Error(fmt::format("{}: writing the OBJ failed (disk full?)", path));
  }
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw Error(fmt::format("{}: cannot move {} into place", path, partial));
  }
}

}  // namespace penumbra
