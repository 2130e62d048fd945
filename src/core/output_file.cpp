#include "core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.h"
#include "core/image_io.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Writes all of `bytes` to `fd`; false with errno set on failure (ENOSPC on a full disk).
bool writeAll(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    done += size_t(n);
  }
  return true;
}

[[noreturn]] void fail(std::string_view what, const std::string& path, int error) {
  throw Error(fmt::format("cannot write {} '{}': {}", what, path, std::strerror(error)));
}

void writeInPlace(const std::string& path, std::string_view bytes, std::string_view what) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail(what, path, errno);
  const bool ok = writeAll(fd, bytes);
  const int write_error = errno;
  if (::close(fd) != 0 && ok) fail(what, path, errno);
  if (!ok) fail(what, path, write_error);
}

}  // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes, std::string_view what) {
  PENUMBRA_CHECK(!path.empty(), "the {} output path is empty", what);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    PENUMBRA_CHECK(!fs::is_directory(status), "cannot write {} '{}': it is a folder", what, path);
    writeInPlace(path, bytes, what);
    return;
  }
  createParentDirectories(path);
  const fs::path target(path);
  const std::string pattern =
      (target.parent_path() / fmt::format(".{}.tmp.XXXXXX", target.filename().string())).string();
  std::vector<char> temp(pattern.begin(), pattern.end());
  temp.push_back('\0');
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(what, path, errno);
  // mkstemp creates the file 0600; give it the mode a plain open would (0666 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask);
  const bool ok = writeAll(fd, bytes);
  int error = errno;
  const bool closed = ::close(fd) == 0;
  if (ok && !closed) error = errno;
  if (!ok || !closed || ::rename(temp.data(), path.c_str()) != 0) {
    if (ok && closed) error = errno;
    ::unlink(temp.data());
    fail(what, path, error);
  }
}

}  // namespace penumbra
