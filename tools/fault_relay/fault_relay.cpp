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
#include <vector>

#include "fault_model.hpp"
#include "posix/command_line.hpp"

namespace {

const minrt::cli::Tool& tool() {
  static const minrt::cli::Tool t{
      "fault-relay",
      R"(Usage: fault-relay [OPTIONS] BOARD_TTY
Relays bytes between BOARD_TTY (e.g. the pseudo-terminal firmware-sim --pty
announced) and a new pseudo-terminal for the host, damaging the line on
purpose and reproducibly. Prints 'fault-relay: uart on /dev/pts/N' on standard
error, and at the end what it did. Probabilities P are 0..1.

)",
      {
          {"seed", 0, "N", "fault sequence (default 1)"},
          {"drop", 0, "P", "probability of dropping a byte"},
          {"flip", 0, "P", "probability of flipping one bit of a byte"},
          {"dup", 0, "P", "probability of sending a byte twice"},
          {"delay", 0, "P", "probability of delaying a byte (up to --delay-ms)"},
          {"delay-ms", 0, "N", "longest delay (default 5)"},
          {"stall", 0, "P", "probability of stalling the line before a byte"},
          {"stall-ms", 0, "N", "stall length (default 300)"},
          {"skip", 0, "N", "pass the first N bytes untouched"},
          {nullptr, 0, nullptr, "Single-byte faults, whatever the rates (N counts from 0):"},
          {"drop-at", 0, "N", "drop board->host byte N"},
          {"dup-at", 0, "N", "send board->host byte N twice"},
          {"flip-at", 0, "N", "flip the lowest bit of board->host byte N"},
          {"to-board-drop-at", 0, "N", "drop host->board byte N"},
          {"to-board-dup-at", 0, "N", "send host->board byte N twice"},
          {"to-board-flip-at", 0, "N", "flip the lowest bit of host->board byte N"},
          {nullptr, 0, nullptr, "Direction (the rates hit board->host bytes by default):"},
          {"both-ways", 0, nullptr, "damage host->board bytes too (own seed + 1)"},
          {"to-board", 0, nullptr, "damage host->board bytes only (own seed + 1)"},
      },
      "\nexit status: 0 the host closed its end, 1 a terminal error, 2 usage error.\n",
      1,
      1,
      "BOARD_TTY"};
  return t;
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
  std::vector<std::string> board_path;
  int status = 0;
  const bool go_on = minrt::cli::parse_tool(
      argc, argv, tool(), MINRT_VERSION,
      [&](const minrt::cli::Option* o, const std::string& text) -> std::string {
        const std::string a = std::string("--") + o->name;
        if (a == "--both-ways") both = true;
        else if (a == "--to-board") both = to_board_only = true;
        if (o->value == nullptr) return "";
        // Every value is a number: a probability, or a count or time >= 0.
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool probability = *o->value == 'P';
        if (text.empty() || *end != 0 || v < 0 || (probability && v > 1) || v > 1e15)
          return "bad " + a + " '" + text + "': expected " + (probability ? "a probability 0..1" : "a number >= 0");
        const auto at = static_cast<std::int64_t>(v);
        if (a == "--seed") seed = static_cast<unsigned long long>(v);
        else if (a == "--drop") rates.drop = v;
        else if (a == "--flip") rates.flip = v;
        else if (a == "--dup") rates.dup = v;
        else if (a == "--delay") rates.delay = v;
        else if (a == "--stall") rates.stall = v;
        else if (a == "--delay-ms") rates.delay_ms = v < 1 ? 1 : static_cast<int>(v);
        else if (a == "--stall-ms") rates.stall_ms = static_cast<int>(v);
        else if (a == "--skip") rates.skip = static_cast<std::uint64_t>(v);
        else if (a == "--drop-at") rates.drop_at = at;
        else if (a == "--dup-at") rates.dup_at = at;
        else if (a == "--flip-at") rates.flip_at = at;
        else if (a == "--to-board-drop-at") up_drop_at = at, both = true;
        else if (a == "--to-board-dup-at") up_dup_at = at, both = true;
        else if (a == "--to-board-flip-at") up_flip_at = at, both = true;
        return "";
      },
      status, &board_path);
  if (!go_on) return status;
  const int board = open_raw(board_path[0].c_str());
  if (board < 0) {
    std::fprintf(stderr, "fault-relay: error: cannot open %s: %s\n", board_path[0].c_str(), std::strerror(errno));
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
