// SerialPort on a pseudo-terminal pair (the openpty arrangement): termios2 rates, raw 8N1, the lock
// and the restoring of the settings.
#include <catch2/catch.hpp>

#include <asm/termbits.h>
#include <fcntl.h>
#include <stdlib.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "port.hpp"

using minrt::send::PortError;
using minrt::send::PortSettings;
using minrt::send::SerialPort;

namespace {

struct PtyPair {
  int master = -1, slave = -1;
  std::string name;
  PtyPair() {
    // openpty() would pull in <termios.h>, which clashes with termios2.
    master = ::posix_openpt(O_RDWR | O_NOCTTY);
    REQUIRE(master >= 0);
    REQUIRE(::grantpt(master) == 0);
    REQUIRE(::unlockpt(master) == 0);
    name = ::ptsname(master);
    slave = ::open(name.c_str(), O_RDWR | O_NOCTTY);
    REQUIRE(slave >= 0);
  }
  ~PtyPair() {
    ::close(master);
    ::close(slave);
  }
};

struct termios2 get2(int fd) {
  struct termios2 t {};
  REQUIRE(::ioctl(fd, TCGETS2, &t) == 0);
  return t;
}

// Puts the tty in a recognisable state (canonical, echo, `baud`) that
// host-send must restore.
void set_cooked(int fd, unsigned baud) {
  struct termios2 t = get2(fd);
  t.c_lflag |= ICANON | ECHO;
  t.c_cflag &= ~CBAUD;
  t.c_cflag |= BOTHER;
  t.c_ospeed = t.c_ispeed = baud;
  REQUIRE(::ioctl(fd, TCSETS2, &t) == 0);
}

}  // namespace

TEST_CASE("termios2 sets any rate, raw 8N1, on a pty", "[port]") {
  PtyPair pty;
  for (unsigned baud : {115200u, 921600u, 3000000u, 250000u, 31250u}) {
    SerialPort port;
    port.open(pty.name, PortSettings{baud, minrt::send::Flow::kNone});
    CHECK(port.applied_baud() == baud);
    CHECK(port.baud_warning().empty());
    const struct termios2 t = get2(port.fd());
    CHECK((t.c_cflag & CBAUD) == BOTHER);
    CHECK(t.c_ospeed == baud);
    CHECK((t.c_cflag & CSIZE) == CS8);
    CHECK((t.c_cflag & (PARENB | CSTOPB | CRTSCTS)) == 0);
    CHECK((t.c_lflag & (ICANON | ECHO | ISIG)) == 0);
    CHECK((t.c_oflag & OPOST) == 0);
  }
}

TEST_CASE("flow control settings reach the driver", "[port]") {
  PtyPair pty;
  SerialPort port;
  port.open(pty.name, PortSettings{115200, minrt::send::Flow::kXonXoff});
  CHECK((get2(port.fd()).c_iflag & (IXON | IXOFF)) == (IXON | IXOFF));
  port.close();
  port.open(pty.name, PortSettings{115200, minrt::send::Flow::kRtsCts});
  // A pty may or may not keep CRTSCTS; it must not fail.
  CHECK(port.is_open());
}

TEST_CASE("the port's settings are restored on close", "[port]") {
  PtyPair pty;
  set_cooked(pty.slave, 9600);
  {
    SerialPort port;
    port.open(pty.name, PortSettings{921600, minrt::send::Flow::kNone});
    CHECK(get2(pty.slave).c_ospeed == 921600);
  }
  const struct termios2 after = get2(pty.slave);
  CHECK(after.c_ospeed == 9600);
  CHECK((after.c_lflag & (ICANON | ECHO)) == (ICANON | ECHO));
}

TEST_CASE("the port is locked (flock and TIOCEXCL) and the holder is named", "[port]") {
  PtyPair pty;
  SerialPort port;
  port.open(pty.name, PortSettings{});
  int excl = 0;
  REQUIRE(::ioctl(port.fd(), TIOCGEXCL, &excl) == 0);
  CHECK(excl == 1);
  port.close();
  REQUIRE(::ioctl(pty.slave, TIOCGEXCL, &excl) == 0);
  CHECK(excl == 0);

  // A child holds the port; our open must fail and name it.
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t child = ::fork();
  if (child == 0) {
    // Catch's handlers would report our SIGTERM as a failed test.
    ::signal(SIGTERM, SIG_DFL);
    SerialPort held;
    try {
      held.open(pty.name, PortSettings{});
    } catch (...) {
      ::_exit(1);
    }
    (void)!::write(ready[1], "x", 1);
    ::pause();
    ::_exit(0);
  }
  char c;
  REQUIRE(::read(ready[0], &c, 1) == 1);
  std::string message;
  try {
    SerialPort second;
    second.open(pty.name, PortSettings{});
  } catch (const PortError& e) {
    message = e.message;
  }
  ::kill(child, SIGTERM);
  ::waitpid(child, nullptr, 0);
  ::close(ready[0]);
  ::close(ready[1]);
  // root passes TIOCEXCL, so the flock is what stops us here.
  CHECK_THAT(message, Catch::Contains(pty.name) && Catch::Contains("pid " + std::to_string(child)));
  // Once the holder is gone the port opens again.
  SerialPort third;
  CHECK_NOTHROW(third.open(pty.name, PortSettings{}));
}

TEST_CASE("opening something that is no serial port fails cleanly", "[port]") {
  SerialPort port;
  CHECK_THROWS_AS(port.open("/dev/null", PortSettings{}), PortError);
  CHECK_THROWS_AS(port.open("/nonexistent/tty", PortSettings{}), PortError);
}

TEST_CASE("bytes pass both ways through an open port", "[port]") {
  PtyPair pty;
  SerialPort port;
  port.open(pty.name, PortSettings{3000000, minrt::send::Flow::kNone});
  const std::string msg = "hello\x11\x13\r\n\x04\xff";
  REQUIRE(port.write_all(msg.data(), msg.size(), 1000));
  char buf[64];
  size_t got = 0;
  while (got < msg.size()) {
    const ssize_t n = ::read(pty.master, buf + got, sizeof buf - got);
    REQUIRE(n > 0);
    got += static_cast<size_t>(n);
  }
  CHECK(std::string(buf, got) == msg);
  REQUIRE(::write(pty.master, "\r\nok\x03", 5) == 5);
  got = 0;
  while (got < 5) {
    const long n = port.read_some(buf + got, sizeof buf - got, 1000);
    REQUIRE(n > 0);
    got += static_cast<size_t>(n);
  }
  CHECK(std::string(buf, 5) == "\r\nok\x03");
  CHECK(port.read_some(buf, sizeof buf, 50) == 0);  // timeout
}

TEST_CASE("host-send restores the port's settings when it is interrupted", "[port][cli]") {
  PtyPair pty;
  set_cooked(pty.slave, 4800);
  const pid_t child = ::fork();
  if (child == 0) {
    const int devnull = ::open("/dev/null", O_RDWR);
    ::dup2(devnull, 1);
    ::dup2(devnull, 2);
    ::execl(HS_HOST_SEND, HS_HOST_SEND, "--no-handshake", "--port", pty.name.c_str(), "--baud", "3000000", HS_DATA_DIR "/../standin_board.cpp",
            "-o", "/tmp/host_send_never.ppm", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Any file serves as the scene: no board answers. Wait until host-send has
  // switched the port to its rate, then interrupt it.
  bool switched = false;
  for (int i = 0; i < 300 && !switched; ++i) {
    ::usleep(10000);
    switched = get2(pty.slave).c_ospeed == 3000000;
  }
  CHECK(switched);
  ::kill(child, SIGTERM);
  int st = 0;
  ::waitpid(child, &st, 0);
  // Ended by the signal itself once the port is back (the shell shows 143).
  CHECK(WIFSIGNALED(st));
  CHECK(WTERMSIG(st) == SIGTERM);
  const struct termios2 after = get2(pty.slave);
  CHECK(after.c_ospeed == 4800);
  CHECK((after.c_lflag & (ICANON | ECHO)) == (ICANON | ECHO));
  CHECK(::access("/tmp/host_send_never.ppm", F_OK) != 0);
}
