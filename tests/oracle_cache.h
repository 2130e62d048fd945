#pragma once
// The oracle's visibility images for a test frame, kept on disk between the test processes of
// one build. ctest runs every test in a process of its own, so a suite that compares many
// techniques with the same 1024-ray oracle would otherwise trace it once per technique (under
// the sanitizers that is most of the suite's time). The oracle is deterministic (seeded
// stratified samples), so a stored image is the image it would render again; the key holds the
// test binary's size and modification time, so a rebuild never reads an older build's images.
// A missing, short or unreadable file is traced again; files are written to a temporary name and
// renamed, so a test running beside this one never reads half a file.
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/image.h"

namespace penumbra::testing {

inline std::filesystem::path oracleCachePath(const std::string& key) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto size = std::filesystem::file_size(exe, ec);
  if (ec) return {};
  const auto stamp = std::filesystem::last_write_time(exe, ec).time_since_epoch().count();
  if (ec) return {};
  const std::filesystem::path dir = exe.parent_path() / "test-oracle-cache";
  std::filesystem::create_directories(dir, ec);
  if (ec) return {};
  return dir / fmt::format("{}-{}-{:x}.f32", key, size, std::hash<long long>{}(stamp));
}

// `count` images of width x height, or nothing when the cache does not hold them.
inline std::optional<std::vector<Image<float>>> loadOracleImages(const std::string& key,
                                                                 size_t count, int width,
                                                                 int height) {
  const std::filesystem::path path = oracleCachePath(key);
  if (path.empty()) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::vector<Image<float>> images(count);
  for (Image<float>& image : images) {
    image.resize(width, height);
    in.read(reinterpret_cast<char*>(image.data()), std::streamsize(image.size() * sizeof(float)));
    if (!in) return std::nullopt;
  }
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;
  return images;
}

inline void storeOracleImages(const std::string& key,
                              const std::vector<const Image<float>*>& images) {
  const std::filesystem::path path = oracleCachePath(key);
  if (path.empty()) return;
  const std::filesystem::path temp = path.string() + fmt::format(".{}.tmp", ::getpid());
  {
    std::ofstream out(temp, std::ios::binary);
    for (const Image<float>* image : images)
      out.write(reinterpret_cast<const char*>(image->data()),
                std::streamsize(image->size() * sizeof(float)));
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      return;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) std::filesystem::remove(temp, ec);
}

}  // namespace penumbra::testing
