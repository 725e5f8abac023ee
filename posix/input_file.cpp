#include "input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace minrt::host {

namespace {
const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return std::strerror(EISDIR);
  if (S_ISFIFO(m)) return "not a regular file (a FIFO)";
  if (S_ISCHR(m) || S_ISBLK(m)) return "not a regular file (a device)";
  if (S_ISSOCK(m)) return "not a regular file (a socket)";
  return "not a regular file";
}

// Opens without blocking and checks the kind; `regular_only` refuses all
// but regular files, otherwise only directories.
int open_checked(const std::string& path, bool regular_only, std::string& error) {
  if (path.empty()) {
    error = std::strerror(ENOENT);
    return -1;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    error = std::strerror(errno);
    return -1;
  }
  struct stat st {};
  const bool stat_ok = ::fstat(fd, &st) == 0;
  const bool refused = !stat_ok || S_ISDIR(st.st_mode) || (regular_only && !S_ISREG(st.st_mode));
  if (refused) {
    error = stat_ok ? kind_of(st.st_mode) : std::strerror(errno);
    ::close(fd);
    return -1;
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}
}  // namespace

int open_regular_file(const std::string& path, std::string& error) { return open_checked(path, true, error); }

int open_input_stream(const std::string& path, std::string& error) { return open_checked(path, false, error); }

bool read_whole_file(const std::string& path, std::string& out, std::string& error, std::size_t max_bytes) {
  out.clear();
  const int fd = open_regular_file(path, error);
  if (fd < 0) return false;
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
  if (S_ISREG(st.st_mode)) out.reserve(static_cast<std::size_t>(st.st_size));
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      error = std::strerror(errno);
      out.clear();
      return false;
    }
    // A pipe or device says nothing up front (and a file may grow while it
    // is read): stop one read past the bound.
    if (out.size() + static_cast<std::size_t>(n) > max_bytes) {
      error = too_large;
      out.clear();
      return false;
    }
    out.append(buf, static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace minrt::host
