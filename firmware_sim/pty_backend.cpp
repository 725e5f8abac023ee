#include "pty_backend.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace fwsim {
namespace {

// Raw mode is a property of the slave's line discipline: no echo, no line
// editing, no CR/LF translation.
void make_raw(const std::string& slave) {
  int s = ::open(slave.c_str(), O_RDWR | O_NOCTTY);
  if (s < 0) throw std::runtime_error("cannot open " + slave + ": " + std::strerror(errno));
  termios t{};
  if (::tcgetattr(s, &t) == 0) {
    ::cfmakeraw(&t);
    ::tcsetattr(s, TCSANOW, &t);
  }
  ::close(s);
}

}  // namespace

int open_uart_pty(const char* who) {
  int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0)
    throw std::runtime_error(std::string("cannot create pty: ") + std::strerror(errno));
  const char* name = ::ptsname(master);
  if (!name) throw std::runtime_error("cannot name pty");
  const std::string slave = name;
  make_raw(slave);
  std::fprintf(stderr, "%s: uart on %s\n", who, slave.c_str());
  std::fflush(stderr);
  // While no process has the slave open, the master reports POLLHUP.
  for (;;) {
    pollfd p{master, POLLIN, 0};
    if (::poll(&p, 1, 50) < 0 && errno != EINTR)
      throw std::runtime_error(std::string("poll on pty: ") + std::strerror(errno));
    if (!(p.revents & POLLHUP)) break;
    ::usleep(20000);
  }
  // Linux resets a pty slave's termios when it is reopened after its last
  // close, so raw mode is applied again now that the host holds it open.
  make_raw(slave);
  return master;
}

int open_uart_pty_for_board(int& held_slave) {
  int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0)
    throw std::runtime_error(std::string("cannot create pty: ") + std::strerror(errno));
  const char* name = ::ptsname(master);
  if (!name) throw std::runtime_error("cannot name pty");
  const std::string slave = name;
  make_raw(slave);
  // Held open for the whole run: the slave's settings stay raw between
  // hosts, and a host's close is silence on the line, not end of input.
  held_slave = ::open(slave.c_str(), O_RDWR | O_NOCTTY);
  if (held_slave < 0) throw std::runtime_error("cannot open " + slave + ": " + std::strerror(errno));
  std::fprintf(stderr, "firmware-sim: uart on %s\n", slave.c_str());
  std::fflush(stderr);
  return master;
}

void drain_uart_pty(int master, int timeout_ms) {
  const char* name = ::ptsname(master);
  if (!name) return;
  int s = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (s < 0) return;
  // Bytes written to the master reach the slave's queue asynchronously, so
  // an empty queue only counts once it has stayed empty for 100 ms.
  int empty_ms = 0;
  for (int waited = 0; waited < timeout_ms && empty_ms < 100; waited += 10) {
    int pending = 0;
    if (::ioctl(s, FIONREAD, &pending) != 0) break;
    empty_ms = pending == 0 ? empty_ms + 10 : 0;
    ::usleep(10000);
  }
  ::close(s);
}

}  // namespace fwsim
