#include "trace_stream.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fwsim {

ssize_t TraceStream::write_cookie(void* self, const char* buf, size_t n) {
  auto* t = static_cast<TraceStream*>(self);
  if (t->err_ != 0) return -1;
  size_t done = 0;
  while (done < n) {
    const ssize_t w = ::write(t->fd_, buf + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      t->err_ = w < 0 ? errno : EIO;
      return -1;
    }
    done += static_cast<size_t>(w);
  }
  return static_cast<ssize_t>(n);
}

bool TraceStream::open(int fd, const std::string& name, std::string& error) {
  name_ = name;
  fd_ = fd;
  cookie_io_functions_t io{};
  io.write = &TraceStream::write_cookie;
  file_ = ::fopencookie(this, "w", io);
  if (file_ == nullptr) {
    error = "cannot open " + name + ": " + std::strerror(errno);
    ::close(fd);
    fd_ = -1;
    return false;
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 16);
  return true;
}

bool TraceStream::close(std::string& error) {
  if (file_ == nullptr) return true;
  bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  std::fclose(file_);
  file_ = nullptr;
  if (::close(fd_) != 0 && ok && errno != EINTR) {
    ok = false;
    err_ = errno;
  }
  fd_ = -1;
  if (!ok) error = "cannot write " + name_ + ": " + std::strerror(err_ != 0 ? err_ : EIO);
  return ok;
}

TraceStream::~TraceStream() {
  if (file_ != nullptr) std::fclose(file_);
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace fwsim
