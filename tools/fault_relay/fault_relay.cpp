// fault-relay: sits between the host and a board's pseudo-terminal and
// damages the line on purpose, reproducibly (seeded).
//
//   fault-relay [OPTIONS] BOARD_TTY
//
// Opens BOARD_TTY (e.g. the pty firmware-sim announced), creates a new pty
// for the host, prints "fault-relay: uart on /dev/pts/N" on stderr and
// relays bytes both ways. Faults hit the board->host direction, and the
// host->board direction too with --both-ways, or only with --to-board. At the end it prints what it
// did ("fault-relay: ... dropped, ... flipped ...").
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "fault_model.hpp"

namespace {

#ifndef MINRT_VERSION
#define MINRT_VERSION "0"
#endif

void print_help() {
  std::fputs(
      "Usage: fault-relay [OPTIONS] BOARD_TTY\n"
      "Relays bytes between BOARD_TTY (e.g. the pseudo-terminal firmware-sim --pty\n"
      "announced) and a new pseudo-terminal for the host, damaging the line on\n"
      "purpose and reproducibly. Prints 'fault-relay: uart on /dev/pts/N' on standard\n"
      "error, and at the end what it did. Probabilities P are 0..1.\n"
      "\n"
      "  --seed N          fault sequence (default 1)\n"
      "  --drop P          probability of dropping a byte\n"
      "  --flip P          probability of flipping one bit of a byte\n"
      "  --dup P           probability of sending a byte twice\n"
      "  --delay P         probability of delaying a byte (up to --delay-ms)\n"
      "  --delay-ms N      longest delay (default 5)\n"
      "  --stall P         probability of stalling the line before a byte\n"
      "  --stall-ms N      stall length (default 300)\n"
      "  --skip N          pass the first N bytes untouched\n"
      "  --drop-at N       drop board->host byte N (0-based), whatever the rates\n"
      "  --dup-at N        send board->host byte N twice\n"
      "  --flip-at N       flip the lowest bit of board->host byte N\n"
      "  --both-ways       damage host->board bytes too (own seed + 1)\n"
      "  --to-board        damage host->board bytes only (own seed + 1)\n"
      "  --to-board-drop-at N, --to-board-dup-at N, --to-board-flip-at N\n"
      "                    the same single-byte faults on host->board byte N\n"
      "  -h, --help        this text\n"
      "  --version         version\n"
      "\n"
      "exit status: 0 the host closed its end, 1 a terminal error, 2 usage error.\n",
      stdout);
}

[[noreturn]] void usage_error(const std::string& msg) {
  std::fprintf(stderr, "fault-relay: error: %s (see fault-relay --help)\n", msg.c_str());
  std::exit(2);
}

int open_raw(const char* path) {
  const int fd = ::open(path, O_RDWR | O_NOCTTY);
  if (fd < 0) return -1;
  termios t{};
  if (::tcgetattr(fd, &t) == 0) {
    ::cfmakeraw(&t);
    ::tcsetattr(fd, TCSANOW, &t);
  }
  return fd;
}

bool write_all(int fd, const std::uint8_t* p, size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<size_t>(k);
  }
  return true;
}

// Forwards `n` bytes through the model.
bool forward(int to, const std::uint8_t* p, size_t n, fault_relay::FaultModel* model) {
  if (model == nullptr) return write_all(to, p, n);
  for (size_t i = 0; i < n; ++i) {
    const fault_relay::Action a = model->next(p[i]);
    if (a.sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(a.sleep_ms));
    for (int c = 0; c < a.copies; ++c)
      if (!write_all(to, &a.value, 1)) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  fault_relay::FaultRates rates;
  unsigned long long seed = 1;
  bool both = false, to_board_only = false;
  std::int64_t up_drop_at = -1, up_dup_at = -1, up_flip_at = -1;
  const char* board_path = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto num = [&](double& v) {
      if (i + 1 >= argc) usage_error(a + " needs a value");
      char* end = nullptr;
      const char* text = argv[++i];
      v = std::strtod(text, &end);
      const bool probability = a == "--drop" || a == "--flip" || a == "--dup" || a == "--delay" || a == "--stall";
      if (end == text || *end != 0 || v < 0 || (probability && v > 1) || v > 1e15)
        usage_error("bad " + a + " '" + text + "': expected " + (probability ? "a probability 0..1" : "a number >= 0"));
    };
    double v = 0;
    if (a == "--seed") { num(v); seed = static_cast<unsigned long long>(v); }
    else if (a == "--drop") num(rates.drop);
    else if (a == "--flip") num(rates.flip);
    else if (a == "--dup") num(rates.dup);
    else if (a == "--delay") num(rates.delay);
    else if (a == "--stall") num(rates.stall);
    else if (a == "--delay-ms") { num(v); rates.delay_ms = v < 1 ? 1 : static_cast<int>(v); }
    else if (a == "--stall-ms") { num(v); rates.stall_ms = static_cast<int>(v); }
    else if (a == "--skip") { num(v); rates.skip = static_cast<std::uint64_t>(v); }
    else if (a == "--drop-at") { num(v); rates.drop_at = static_cast<std::int64_t>(v); }
    else if (a == "--dup-at") { num(v); rates.dup_at = static_cast<std::int64_t>(v); }
    else if (a == "--flip-at") { num(v); rates.flip_at = static_cast<std::int64_t>(v); }
    else if (a == "--both-ways") both = true;
    else if (a == "--to-board") both = to_board_only = true;
    else if (a == "--to-board-drop-at") { num(v); up_drop_at = static_cast<std::int64_t>(v); both = true; }
    else if (a == "--to-board-dup-at") { num(v); up_dup_at = static_cast<std::int64_t>(v); both = true; }
    else if (a == "--to-board-flip-at") { num(v); up_flip_at = static_cast<std::int64_t>(v); both = true; }
    else if (a == "-h" || a == "--help") { print_help(); return 0; }
    else if (a == "--version") { std::printf("fault-relay %s\n", MINRT_VERSION); return 0; }
    else if (!a.empty() && a[0] == '-') usage_error("unknown option '" + a + "'");
    else if (board_path != nullptr) usage_error("more than one BOARD_TTY given");
    else board_path = argv[i];
  }
  if (board_path == nullptr) usage_error("no BOARD_TTY given");
  const int board = open_raw(board_path);
  if (board < 0) {
    std::fprintf(stderr, "fault-relay: error: cannot open %s: %s\n", board_path, std::strerror(errno));
    return 1;
  }
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
    std::fprintf(stderr, "fault-relay: error: cannot open a pseudo-terminal: %s\n", std::strerror(errno));
    return 1;
  }
  const char* name = ::ptsname(master);
  if (const int s = open_raw(name); s >= 0) ::close(s);
  std::fprintf(stderr, "fault-relay: uart on %s\n", name);
  std::fflush(stderr);
  // Wait for the host to open its end.
  for (;;) {
    pollfd p{master, POLLIN, 0};
    ::poll(&p, 1, 50);
    if (!(p.revents & POLLHUP)) break;
    ::usleep(10000);
  }
  fault_relay::FaultRates up_rates = rates;  // --drop-at and the like are board->host only
  up_rates.drop_at = up_drop_at;
  up_rates.dup_at = up_dup_at;
  up_rates.flip_at = up_flip_at;
  if (up_drop_at >= 0 || up_dup_at >= 0 || up_flip_at >= 0) {
    if (!to_board_only) up_rates.drop = up_rates.flip = up_rates.dup = up_rates.delay = up_rates.stall = 0;
  }
  fault_relay::FaultRates down_rates = rates;
  if (to_board_only) {
    down_rates = fault_relay::FaultRates{};
    down_rates.drop_at = rates.drop_at;
    down_rates.dup_at = rates.dup_at;
    down_rates.flip_at = rates.flip_at;
  }
  fault_relay::FaultModel down(seed, down_rates), up(seed + 1, up_rates);
  std::uint8_t buf[4096];
  bool board_open = true;
  for (;;) {
    pollfd p[2] = {{master, POLLIN, 0}, {board, static_cast<short>(board_open ? POLLIN : 0), 0}};
    ::poll(p, 2, 200);
    if (p[0].revents & POLLIN) {
      const ssize_t n = ::read(master, buf, sizeof buf);
      if (n <= 0) break;
      if (board_open && !forward(board, buf, static_cast<size_t>(n), both ? &up : nullptr)) board_open = false;
    } else if (p[0].revents & POLLHUP) {
      break;  // the host closed its end
    }
    if (board_open && (p[1].revents & (POLLIN | POLLHUP | POLLERR))) {
      const ssize_t n = ::read(board, buf, sizeof buf);
      if (n <= 0) board_open = false;  // board gone: keep the host's end open until it closes
      else if (!forward(master, buf, static_cast<size_t>(n), &down)) break;
    }
  }
  std::fprintf(stderr, "fault-relay: board->host %s\n", down.counts().summary().c_str());
  if (both) std::fprintf(stderr, "fault-relay: host->board %s\n", up.counts().summary().c_str());
  ::close(board);
  ::close(master);
  return 0;
}
