#include "file_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace minrt::host {

bool read_whole_file(const std::string& path, std::string& out, std::string& error, std::size_t max_bytes) {
  out.clear();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return false;
  }
  const bool ok = read_whole_fd(fd, out, error, max_bytes);
  ::close(fd);
  return ok;
}

bool read_whole_fd(int fd, std::string& out, std::string& error, std::size_t max_bytes) {
  out.clear();
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
    error = S_ISDIR(st.st_mode) ? std::strerror(EISDIR) : std::strerror(errno);
    return false;
  }
  const std::string too_large = "larger than " + std::to_string(max_bytes) + " bytes";
  // A regular file says its size up front: refuse it before reading.
  if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes) {
    error = too_large;
    return false;
  }
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      error = std::strerror(errno);
      return false;
    }
    // A pipe or device says nothing up front: stop one read past the bound.
    if (out.size() + static_cast<std::size_t>(n) > max_bytes) {
      error = too_large;
      out.clear();
      return false;
    }
    out.append(buf, static_cast<std::size_t>(n));
  }
  return true;
}

bool read_scene_file(const std::string& path, std::string& text, std::size_t max_bytes) {
  if (path == "-") return true;
  std::string why;
  if (read_whole_file(path, text, why, max_bytes)) return true;
  std::fprintf(stderr, "minrt: error: cannot read %s: %s\n", path.c_str(), why.c_str());
  return false;
}

}  // namespace minrt::host
