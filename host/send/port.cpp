// termios2 needs the kernel's <asm/termbits.h>, which cannot be mixed with
// glibc's <termios.h>; this file uses only the former.
#include "port.hpp"

#include "posix/interrupt.hpp"

#include <asm/termbits.h>
#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

static_assert(sizeof(struct termios2) <= 64, "saved settings buffer too small");

namespace minrt::send {

namespace {

std::string read_small_file(const std::string& path) {
  std::string out;
  if (FILE* f = std::fopen(path.c_str(), "r")) {
    char buf[256];
    const std::size_t n = std::fread(buf, 1, sizeof buf, f);
    out.assign(buf, n);
    std::fclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' ')) out.pop_back();
  return out;
}

// The same raw settings glibc's cfmakeraw applies, on a termios2.
void make_raw(struct termios2& t) {
  t.c_iflag &= ~static_cast<tcflag_t>(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON);
  t.c_oflag &= ~static_cast<tcflag_t>(OPOST);
  t.c_lflag &= ~static_cast<tcflag_t>(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB);
  t.c_cflag |= CS8;
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
}

long long now_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string describe_holders(const std::string& device) {
  struct stat target {};
  if (::stat(device.c_str(), &target) != 0) return "";
  std::string out;
  const pid_t self = ::getpid();
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return "";
  while (dirent* e = ::readdir(proc)) {
    char* end = nullptr;
    const long pid = std::strtol(e->d_name, &end, 10);
    if (*end != 0 || pid <= 0 || pid == self) continue;
    const std::string fd_dir = std::string("/proc/") + e->d_name + "/fd";
    DIR* fds = ::opendir(fd_dir.c_str());
    if (fds == nullptr) continue;
    bool holds = false;
    while (dirent* f = ::readdir(fds)) {
      if (f->d_name[0] == '.') continue;
      struct stat st {};
      if (::stat((fd_dir + "/" + f->d_name).c_str(), &st) == 0 && S_ISCHR(st.st_mode) &&
          st.st_rdev == target.st_rdev) {
        holds = true;
        break;
      }
    }
    ::closedir(fds);
    if (holds) {
      if (!out.empty()) out += ", ";
      out += "pid " + std::to_string(pid) + " (" + read_small_file(std::string("/proc/") + e->d_name + "/comm") + ")";
    }
  }
  ::closedir(proc);
  return out;
}

SerialPort::~SerialPort() { close(); }

void SerialPort::open(const std::string& device, const PortSettings& settings) {
  close();
  device_ = device;
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    std::string msg = "cannot open " + device + ": " + std::strerror(err);
    if (err == EBUSY) {
      const std::string who = describe_holders(device);
      msg += who.empty() ? " (in exclusive use)" : " (in use by " + who + ")";
    }
    throw PortError{msg};
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    std::string msg = "cannot lock " + device + ": ";
    if (err == EWOULDBLOCK) {
      const std::string who = describe_holders(device);
      msg += who.empty() ? "locked by another process" : "locked by " + who;
    } else {
      msg += std::strerror(err);
    }
    throw PortError{msg};
  }
  struct termios2 t {};
  if (::ioctl(fd, TCGETS2, &t) != 0) {
    const int err = errno;
    ::close(fd);
    throw PortError{device + " is not a serial port: " + std::strerror(err)};
  }
  if (::ioctl(fd, TIOCEXCL) != 0) {
    const int err = errno;
    ::close(fd);
    throw PortError{"cannot get exclusive use of " + device + ": " + std::strerror(err)};
  }
  std::memcpy(saved_, &t, sizeof t);
  saved_valid_ = true;
  fd_ = fd;
  // Every signal that ends host-send puts them back too, a fault included.
  minrt::host::restore_on_signal(fd, TCSETS2, saved_, sizeof t);

  make_raw(t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS | CBAUD | (CBAUD << IBSHIFT));
  t.c_cflag |= CREAD | CLOCAL | BOTHER | (BOTHER << IBSHIFT);
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  if (settings.flow == Flow::kRtsCts) t.c_cflag |= CRTSCTS;
  if (settings.flow == Flow::kXonXoff) t.c_iflag |= IXON | IXOFF;
  t.c_ispeed = settings.baud;
  t.c_ospeed = settings.baud;
  if (::ioctl(fd, TCSETS2, &t) != 0) {
    const int err = errno;
    close();
    throw PortError{"cannot set " + std::to_string(settings.baud) + " baud 8N1 on " + device + ": " +
                    std::strerror(err)};
  }
  struct termios2 back {};
  if (::ioctl(fd, TCGETS2, &back) == 0) {
    applied_baud_ = back.c_ospeed;
    const double want = settings.baud;
    const double got = back.c_ospeed;
    if (got < want * 0.98 || got > want * 1.02) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s runs at %u baud, not the requested %u (%.1f%% off)", device.c_str(),
                    static_cast<unsigned>(back.c_ospeed), static_cast<unsigned>(settings.baud),
                    want > 0 ? (got - want) * 100.0 / want : 0.0);
      baud_warning_ = buf;
    }
    if ((back.c_cflag & CSIZE) != CS8 || (back.c_cflag & PARENB) != 0) {
      close();
      throw PortError{device + " did not accept 8N1"};
    }
  }
  ::ioctl(fd, TCFLSH, TCIFLUSH);
}

void SerialPort::close() {
  if (fd_ < 0) return;
  if (saved_valid_) {
    ::ioctl(fd_, TCSETS2, reinterpret_cast<struct termios2*>(saved_));
    saved_valid_ = false;
  }
  minrt::host::forget_restore();
  ::ioctl(fd_, TIOCNXCL);
  ::flock(fd_, LOCK_UN);
  ::close(fd_);
  fd_ = -1;
}

bool SerialPort::write_all(const void* data, std::size_t size, int deadline_ms) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  const long long end = deadline_ms < 0 ? -1 : now_ms() + deadline_ms;
  while (size > 0) {
    if (minrt::host::interrupted()) {
      errno = EINTR;
      return false;
    }
    const ssize_t n = ::write(fd_, p, size);
    if (n > 0) {
      p += n;
      size -= static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) return false;
    int wait = 200;
    if (end >= 0) {
      const long long left = end - now_ms();
      if (left <= 0) {
        errno = ETIMEDOUT;
        return false;
      }
      if (left < wait) wait = static_cast<int>(left);
    }
    pollfd pfd{fd_, POLLOUT, 0};
    ::poll(&pfd, 1, wait);
  }
  return true;
}

long SerialPort::read_some(void* data, std::size_t size, int timeout_ms) {
  const long long end = timeout_ms < 0 ? -1 : now_ms() + timeout_ms;
  for (;;) {
    if (minrt::host::interrupted()) {
      errno = EINTR;
      return -1;
    }
    const ssize_t n = ::read(fd_, data, size);
    if (n > 0) return n;
    if (n == 0) {
      errno = EPIPE;
      return -1;
    }
    if (errno != EAGAIN && errno != EINTR) return -1;
    int wait = 100;  // wake up now and then to notice signals
    if (end >= 0) {
      const long long left = end - now_ms();
      if (left <= 0) return 0;
      if (left < wait) wait = static_cast<int>(left);
    }
    pollfd pfd{fd_, POLLIN, 0};
    ::poll(&pfd, 1, wait);
  }
}

void SerialPort::drain() {
  if (fd_ >= 0) ::ioctl(fd_, TCSBRK, 1);
}

void SerialPort::flush_input() {
  if (fd_ >= 0) ::ioctl(fd_, TCFLSH, TCIFLUSH);
}

}  // namespace minrt::send
