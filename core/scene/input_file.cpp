#include "core/scene/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace pbr {

namespace {

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

}  // namespace

void requireRegularFile(const std::string& path, uint64_t maxBytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(path + ": not a regular file (" + kindOf(st.st_mode) + ")");
  if (static_cast<uint64_t>(st.st_size) > maxBytes) {
    throw std::runtime_error(path + ": " + std::to_string(st.st_size) + " bytes, over the input limit of " +
                             std::to_string(maxBytes));
  }
}

std::string readInputFile(const std::string& path, uint64_t maxBytes) {
  requireRegularFile(path, maxBytes);
  // read(2) itself, so that a failure is the system's reason (a stream throws its own text for /proc/self/mem), and
  // bounded, since files of /proc report a size of 0 whatever they hold.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      throw std::runtime_error(path + ": cannot read: " + std::strerror(error));
    }
    bytes.append(buffer, static_cast<size_t>(n));
    if (bytes.size() > maxBytes) {
      ::close(fd);
      throw std::runtime_error(path + ": over the input limit of " + std::to_string(maxBytes) + " bytes");
    }
  }
  ::close(fd);
  return bytes;
}

}  // namespace pbr
