// The session's host side (protocol/session.hpp): greets the board, reads
// its identity, sends the run's options. Each failure is one line that says
// what happened and what to check (reset, baud, cable, board file).
#pragma once

#include <map>
#include <string>

#include "port.hpp"

namespace minrt::send {

struct BoardIdentity {
  std::string line;                           // as received, without lead and '\n'
  std::map<std::string, std::string> fields;  // key -> value
  std::string get(const std::string& key) const {
    const auto it = fields.find(key);
    return it == fields.end() ? "" : it->second;
  }
};

struct GreetResult {
  enum class Status { kOk, kSilent, kGarbled, kBusy, kLinkError } status = Status::kSilent;
  std::string message;     // the one line, for anything but kOk
  std::string note;        // kOk: what was drained first, or ""
  BoardIdentity identity;
};

// Greets up to `attempts` times, waiting `answer_ms` for the first answer
// and twice as long as before for each next one; bytes from an earlier
// reply still coming are drained (up to `drain_ms` in all) and the board
// greeted again. `baud` goes into the messages.
GreetResult greet_board(SerialPort& port, unsigned baud, int answer_ms = 1500, int attempts = 3,
                        int drain_ms = 60000);

struct RunOptions {
  int width = 0, height = 0;
  bool p6 = false;
  const char* protocol = "raw";
  bool big_endian = false;
};

// Sends the options line and waits (up to `answer_ms`) for the board's
// acceptance; false with the one-line reason (the board's refusal, or no
// answer) in `error`; `refused` when the board said no.
bool send_run_options(SerialPort& port, const RunOptions& options, std::string& error, bool& refused,
                      int answer_ms = 5000);

// "board qemu-virt: rv32imf, ..." lines for --probe.
std::string describe_identity(const BoardIdentity& id);

}  // namespace minrt::send
