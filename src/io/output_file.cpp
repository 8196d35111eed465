#include "io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "base/error.h"
#include "io/echo.h"

namespace tidepool::io {

void replaceFile(const std::filesystem::path& file, std::span<const std::uint8_t> bytes) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  const auto fail = [&](const char* step) {
    const std::string why = std::strerror(errno);
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw Error("cannot write '" + shownPath(file) + "': " + step + why);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("");
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int saved = n < 0 ? errno : ENOSPC;  // a write of 0 bytes: no room left
      ::close(fd);
      errno = saved;
      fail("");
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) fail("");
  if (::rename(tmp.c_str(), file.c_str()) != 0) fail("rename: ");
}

}  // namespace tidepool::io
